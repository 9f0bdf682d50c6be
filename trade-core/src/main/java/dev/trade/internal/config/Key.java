package dev.trade.internal.config;

import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * Every configuration key, in canonical order, with its default and how its value is parsed.
 *
 * <p>Names are TRADE's own and are matched case-sensitively, so that a file that works here also
 * works with TRADE. The order is TRADE's keys first, then ours; {@link Settings#asMap()}, the
 * shipped {@code config/trade.properties} and {@code docs/configuration.md} follow it.
 */
enum Key {
  CONTAINERNAME("", Values::containerName, Values::plain),
  STARTDISCOVERY("false", Values::bool, Values::plain),
  STARTBROADCAST("false", Values::bool, Values::plain),
  MCAST_ADDR("230.1.1.1", Values::multicast, Values::hostAddress),
  BROADCASTPORT("33333", Values.integer("port", 1, 65535), Values::plain),
  BROADCASTINTERVAL("3000", Values.millis(1), Values::millisText),
  DISCOVERYTIMEOUT("3000", Values.millis(0), Values::millisText),
  CALLCONTAINERDISCOVERYTIMEOUT("3000", Values.millis(0), Values::millisText),
  STARTACCEPTINGCONNECTIONS("false", Values::bool, Values::plain),
  SERVERIPS("", Values::listenAddresses, Values::commaList),
  CONNECTCONTAINERS("", Values::connectAddresses, Values::commaList),
  SCANFORSERVER("true", Values::bool, Values::plain),
  TIMEOUT_CLIENT_SOCKET("3000", Values.millis(1), Values::millisText),
  CALLCHECKTIME("5000", Values.millis(1), Values::millisText),
  USEENCRYPTION("false", Values::bool, Values::plain),
  CREDENTIALS("diarcUser", Values::text, Values::plain),
  TRADESYSID("diarc", Values::systemId, Values::plain),
  COPYDATAFORLOCALINVOKES("false", Values::bool, Values::plain),
  CALLTIMEOUT("30000", Values.millis(1), Values::millisText),
  HEARTBEATINTERVAL("250", Values.millis(1), Values::millisText),
  FAILURETIMEOUT("3000", Values.millis(1), Values::millisText),
  DISCOVERYRANGE("localhost", Values::discoveryRange, Values::plain),
  DISCOVERYINTERFACES("", Values::interfaces, Values::commaList),
  SERIALIZATIONALLOWLIST("", Values::allowList, Values::semicolonList),
  MAXFRAMESIZE("67108864", Values.integer("size in bytes", 1024, Integer.MAX_VALUE - 8),
      Values::plain);

  /** Keys TRADE used to read that are accepted and ignored, so that old files still load. */
  static final Set<String> LEGACY = Set.of("RUNWEBSERVER");

  private static final Map<String, Key> BY_NAME = Collections.unmodifiableMap(
      Arrays.stream(values()).collect(Collectors.toMap(
          Key::name, k -> k, (a, b) -> a, LinkedHashMap::new)));

  private final String defaultText;
  private final Function<String, ?> parser;
  private final Function<Object, String> formatter;

  Key(String defaultText, Function<String, ?> parser, Function<Object, String> formatter) {
    this.defaultText = defaultText;
    this.parser = parser;
    this.formatter = formatter;
  }

  /**
   * Returns the key named exactly {@code name}.
   *
   * @throws IllegalArgumentException naming the key and the closest known key
   */
  static Key named(String name) {
    Key key = BY_NAME.get(name);
    if (key == null) {
      throw new IllegalArgumentException(unknownKeyMessage(name));
    }
    return key;
  }

  /**
   * Parses {@code text} for this key; the text is trimmed, and empty text means the default.
   *
   * @throws IllegalArgumentException "KEY=value: expected ...". The value of CREDENTIALS is
   *     shown as {@code ****} because messages end up in logs.
   */
  Object parse(String text) {
    String s = text.trim();
    if (s.isEmpty()) {
      s = defaultText; // defaults are valid: Settings parses them all when it is loaded
    }
    try {
      return parser.apply(s);
    } catch (IllegalArgumentException e) {
      String shown = this == CREDENTIALS ? "****" : s;
      throw new IllegalArgumentException(name() + "=" + shown + ": " + e.getMessage());
    }
  }

  /** The canonical text for a value of this key; {@link #parse} accepts it again. */
  String format(Object value) {
    return formatter.apply(value);
  }

  private static String unknownKeyMessage(String name) {
    Key best = null;
    int bestDistance = Integer.MAX_VALUE;
    String upper = name.toUpperCase(Locale.ROOT); // "broadcastport" should point at the real key
    for (Key k : values()) {
      int d = distance(upper, k.name());
      if (d < bestDistance) {
        best = k;
        bestDistance = d;
      }
    }
    // A suggestion further away than this is noise rather than help.
    if (bestDistance <= Math.max(2, name.length() / 3)) {
      return "unknown key '" + name + "' (did you mean " + best + "?)";
    }
    return "unknown key '" + name + "' (known keys: " + String.join(", ", BY_NAME.keySet()) + ")";
  }

  /** Levenshtein distance: insertions, deletions and substitutions each cost 1. */
  static int distance(String a, String b) {
    int[] previous = new int[b.length() + 1];
    int[] current = new int[b.length() + 1];
    for (int j = 0; j <= b.length(); j++) {
      previous[j] = j;
    }
    for (int i = 1; i <= a.length(); i++) {
      current[0] = i;
      for (int j = 1; j <= b.length(); j++) {
        int substitution = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
        current[j] = Math.min(substitution, Math.min(previous[j], current[j - 1]) + 1);
      }
      int[] swap = previous;
      previous = current;
      current = swap;
    }
    return previous[b.length()];
  }
}
