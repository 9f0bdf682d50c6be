package dev.trade.internal.config;

import java.net.InetAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.StringJoiner;
import java.util.regex.Pattern;

/**
 * Parsers and formatters for each kind of setting value.
 *
 * <p>A parser receives trimmed, non-empty text and either returns an immutable value or throws an
 * {@link IllegalArgumentException} whose message says what was expected ("expected true or
 * false"); {@link Key#parse} puts the key and the bad value in front. A formatter turns the value
 * back into canonical text that its parser accepts again. Stateless and safe for concurrent use.
 */
final class Values {
  /** Largest millisecond count: fits the {@code int} timeouts of the socket API. */
  static final long MAX_MILLIS = Integer.MAX_VALUE;

  private Values() {}

  /**
   * Patterns needed only for keys that are rarely set (their defaults are empty), compiled on
   * first use rather than with the defaults that every container parses.
   */
  private static final class Patterns {
    static final String IDENT = "\\p{javaJavaIdentifierStart}\\p{javaJavaIdentifierPart}*";
    static final String QUALIFIED = IDENT + "(\\." + IDENT + ")*";
    // ObjectInputFilter class patterns: name, name.*, name.**, or name*. Not module/...: the
    // allow-list judges class names alone (the codec's AllowList refuses the form too).
    static final Pattern CLASS_PATTERN =
        Pattern.compile(QUALIFIED + "(\\.\\*\\*?|\\*)?");
    static final Pattern INTERFACE_NAME = Pattern.compile("[^\\p{Cntrl}\\s,;/]+");
  }

  static Object text(String s) {
    if (hasControl(s)) {
      throw expected("text without control characters");
    }
    return s;
  }

  /** A system id: it travels in every announcement and handshake, in at most 64 UTF-8 bytes. */
  static Object systemId(String s) {
    return bounded(s, 1, 64, "a system id of 1 to 64 bytes without control characters");
  }

  /** A container name: it travels in announcements and handshakes, in at most 255 UTF-8 bytes. */
  static Object containerName(String s) {
    return bounded(s, 0, 255, "a name of at most 255 bytes without control characters");
  }

  private static Object bounded(String s, int min, int max, String what) {
    int bytes = s.getBytes(java.nio.charset.StandardCharsets.UTF_8).length;
    if (bytes < min || bytes > max || hasControl(s)) {
      throw expected(what);
    }
    return s;
  }

  /** Strict on the word, lenient on case: {@code yes}, {@code 1} or {@code on} are typos here. */
  static Object bool(String s) {
    if (s.equalsIgnoreCase("true")) {
      return Boolean.TRUE;
    }
    if (s.equalsIgnoreCase("false")) {
      return Boolean.FALSE;
    }
    throw expected("true or false");
  }

  private static boolean hasControl(String s) {
    for (int i = 0; i < s.length(); i++) {
      if (Character.isISOControl(s.charAt(i))) {
        return true;
      }
    }
    return false;
  }

  /** Decimal integers from {@code min} to {@code max}, described as "a {what} min..max". */
  static Object integer(String s, String what, int min, int max) {
    long n = parseLong(s);
    if (n < min || n > max) {
      throw expected("a " + what + " " + min + ".." + max);
    }
    return (int) n;
  }

  /** Whole milliseconds from {@code min} to {@link #MAX_MILLIS}, as a {@link Duration}. */
  static Object millis(String s, long min) {
    long n = parseLong(s);
    if (n < min || n > MAX_MILLIS) {
      throw expected("a duration in milliseconds " + min + ".." + MAX_MILLIS);
    }
    return Duration.ofMillis(n);
  }

  static Object multicast(String s) {
    InetAddress address = Addresses.literal(s);
    if (address == null || !address.isMulticastAddress()) {
      throw expected("a multicast address 224.0.0.0..239.255.255.255 or ff00::/8");
    }
    return address;
  }

  /** {@code SERVERIPS}: where to listen, so port 0 (any free port) is allowed. */
  static Object listenAddresses(String s) {
    return PeerAddress.parseList(s);
  }

  /** {@code CONNECTCONTAINERS}: where to connect, so the port must be real. */
  static Object connectAddresses(String s) {
    List<PeerAddress> list = PeerAddress.parseList(s);
    for (PeerAddress a : list) {
      if (a.anyPort()) {
        throw new IllegalArgumentException("'" + a + "': expected a port 1..65535"
            + " (port 0, any free port, is only allowed in SERVERIPS)");
      }
    }
    return list;
  }

  static Object discoveryRange(String s) {
    for (DiscoveryRange r : DiscoveryRange.values()) {
      if (r.name().equalsIgnoreCase(s)) {
        return r;
      }
    }
    throw expected("localhost or subnet");
  }

  /** Interface names separated by commas or white space; duplicates dropped, order kept. */
  static Object interfaces(String s) {
    if (s.isBlank()) {
      return List.of(); // the default: no need to compile the separator pattern
    }
    Set<String> names = new LinkedHashSet<>();
    for (String name : s.split("[,\\s]+")) {
      if (name.isEmpty()) {
        continue; // blank text, or a leading separator
      }
      if (!Patterns.INTERFACE_NAME.matcher(name).matches()) {
        throw expected("network interface names separated by commas or spaces, e.g. eth0,wlan0");
      }
      names.add(name);
    }
    return List.copyOf(names);
  }

  /**
   * {@code ;}-separated class patterns. Only patterns that allow classes are accepted: a
   * rejection ({@code !...}), a limit ({@code maxdepth=...}) or a catch-all ({@code *}) would
   * change the built-in filter instead of extending it. The same forms as the codec's allow-list
   * takes, so that settings that load also build a container.
   */
  static Object allowList(String s) {
    List<String> patterns = new ArrayList<>();
    for (String p : s.split(";")) {
      String pattern = p.trim();
      if (pattern.isEmpty()) {
        continue; // a trailing ';' is harmless
      }
      if (pattern.indexOf('/') >= 0) {
        throw new IllegalArgumentException("'" + pattern + "': a module prefix (module/) is not"
            + " supported: name the classes or packages alone, e.g. java.time.**");
      }
      if (!Patterns.CLASS_PATTERN.matcher(pattern).matches()) {
        throw new IllegalArgumentException("'" + pattern + "': expected ';'-separated class"
            + " patterns such as com.example.Dto;com.example.model.*;com.example.**");
      }
      if (!patterns.contains(pattern)) {
        patterns.add(pattern);
      }
    }
    return List.copyOf(patterns);
  }

  static String millisText(Object value) {
    return Long.toString(((Duration) value).toMillis());
  }

  static String hostAddress(Object value) {
    return ((InetAddress) value).getHostAddress();
  }

  /** The elements of a list value, separated by {@code separator}. */
  static String joined(Object value, String separator) {
    StringJoiner joiner = new StringJoiner(separator);
    for (Object element : (List<?>) value) {
      joiner.add(String.valueOf(element));
    }
    return joiner.toString();
  }

  /** Parses digits (with an optional sign) as a long, or returns {@link Long#MIN_VALUE}. */
  private static long parseLong(String s) {
    try {
      return Long.parseLong(s);
    } catch (NumberFormatException e) {
      return Long.MIN_VALUE; // below every range, so the caller reports its expected range
    }
  }

  private static IllegalArgumentException expected(String what) {
    return new IllegalArgumentException("expected " + what);
  }
}
