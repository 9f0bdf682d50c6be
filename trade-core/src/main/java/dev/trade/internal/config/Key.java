package dev.trade.internal.config;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * Every configuration key, in canonical order, with its default and how its value is parsed.
 *
 * <p>Names are TRADE's own and are matched case-sensitively, so that a file that works here also
 * works with TRADE. The order is TRADE's keys first, then ours; {@link Settings#asMap()}, the
 * shipped {@code config/trade.properties} and {@code docs/configuration.md} follow it.
 */
enum Key {
  CONTAINERNAME("", ValueType.CONTAINER_NAME),
  STARTDISCOVERY("false", ValueType.BOOL),
  STARTBROADCAST("false", ValueType.BOOL),
  MCAST_ADDR("230.1.1.1", ValueType.MULTICAST),
  BROADCASTPORT("33333", ValueType.PORT),
  BROADCASTINTERVAL("3000", ValueType.MILLIS),
  DISCOVERYTIMEOUT("3000", ValueType.MILLIS_OR_ZERO),
  CALLCONTAINERDISCOVERYTIMEOUT("3000", ValueType.MILLIS_OR_ZERO),
  STARTACCEPTINGCONNECTIONS("false", ValueType.BOOL),
  SERVERIPS("", ValueType.LISTEN_ADDRESSES),
  CONNECTCONTAINERS("", ValueType.CONNECT_ADDRESSES),
  SCANFORSERVER("true", ValueType.BOOL),
  TIMEOUT_CLIENT_SOCKET("3000", ValueType.MILLIS),
  CALLCHECKTIME("5000", ValueType.MILLIS),
  USEENCRYPTION("false", ValueType.BOOL),
  CREDENTIALS("diarcUser", ValueType.TEXT),
  TRADESYSID("diarc", ValueType.SYSTEM_ID),
  COPYDATAFORLOCALINVOKES("false", ValueType.BOOL),
  KEEPTRYING("true", ValueType.BOOL),
  NETWORKINTERFACE("", ValueType.INTERFACES),
  CALLTIMEOUT("30000", ValueType.MILLIS),
  HEARTBEATINTERVAL("1000", ValueType.MILLIS),
  FAILURETIMEOUT("3000", ValueType.MILLIS),
  DISCOVERYRANGE("localhost", ValueType.DISCOVERY_RANGE),
  DISCOVERYINTERFACES("", ValueType.INTERFACES),
  DISCOVERYCLOCKSKEW("30000", ValueType.MILLIS_OR_ZERO),
  SERIALIZATIONALLOWLIST("", ValueType.ALLOW_LIST),
  MAXFRAMESIZE("67108864", ValueType.FRAME_SIZE),
  PRINCIPALSFILE("", ValueType.TEXT),
  PRINCIPAL("", ValueType.TEXT),
  PROVIDERCLASSES("", ValueType.ALLOW_LIST),
  HOOKTIMEOUT("1000", ValueType.MILLIS),
  HOOKSYSTEMSERVICES("false", ValueType.BOOL),
  CALLLOG("", ValueType.TEXT),
  CALLLOGGROUPS("", ValueType.TEXT),
  CALLLOGMAXBYTES("10485760", ValueType.FRAME_SIZE);

  /** Keys TRADE used to read that are accepted and ignored, so that old files still load. */
  static final Set<String> LEGACY = Set.of("RUNWEBSERVER");

  private static final Map<String, Key> BY_NAME = byName();

  private final String defaultText;
  private final ValueType type;

  Key(String defaultText, ValueType type) {
    this.defaultText = defaultText;
    this.type = type;
  }

  private static Map<String, Key> byName() {
    Map<String, Key> map = new LinkedHashMap<>();
    for (Key k : values()) {
      map.put(k.name(), k);
    }
    return Collections.unmodifiableMap(map);
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
   * @throws IllegalArgumentException "KEY=value: expected ...". The values of CREDENTIALS and
   *     PRINCIPAL are shown as {@code ****} because messages end up in logs.
   */
  Object parse(String text) {
    String s = text.trim();
    if (s.isEmpty()) {
      s = defaultText; // defaults are valid: Settings parses them all when it is loaded
    }
    try {
      return type.parse(s);
    } catch (IllegalArgumentException e) {
      String shown = isSecret() ? "****" : s;
      throw new IllegalArgumentException(name() + "=" + shown + ": " + e.getMessage());
    }
  }

  /** Whether the value holds a secret: never shown in messages or {@code Settings.toString()}. */
  boolean isSecret() {
    return this == CREDENTIALS || this == PRINCIPAL;
  }

  /** The canonical text for a value of this key; {@link #parse} accepts it again. */
  String format(Object value) {
    return type.format(value);
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
