package dev.trade.internal.config;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.Set;

/**
 * A container's network address as TRADE writes it: {@code host@port}, for example
 * {@code 127.0.0.1@10002}.
 *
 * <p>The host is an IPv4 literal, a host name, or an IPv6 literal. IPv6 may be written with or
 * without brackets ({@code [::1]@10002} or {@code ::1@10002}) because the text is split at the
 * <em>last</em> {@code @}. The host is stored without brackets and in lower case (host names and
 * IPv6 hex digits are case-insensitive), so equal addresses compare equal. Nothing is resolved:
 * a host name is only checked for syntax.
 *
 * <p>Port 0 means "any free port". It only makes sense for an address to listen on, so
 * {@link Settings} accepts it in {@code SERVERIPS} and refuses it in {@code CONNECTCONTAINERS};
 * this record itself allows 0..65535. Instances are immutable and safe for concurrent use.
 *
 * @param host an IPv4 literal, host name, or IPv6 literal (without brackets, with an optional
 *     {@code %zone})
 * @param port 0..65535; 0 means any free port
 */
public record PeerAddress(String host, int port) {
  static final String EXAMPLES = "e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002";

  /**
   * @throws IllegalArgumentException if the host is not valid or the port is outside 0..65535
   */
  public PeerAddress {
    Objects.requireNonNull(host, "host == null");
    if (!Addresses.isHost(host)) {
      throw new IllegalArgumentException(
          "'" + host + "': expected an IPv4 address, host name or IPv6 address");
    }
    if (port < 0 || port > 65535) {
      throw new IllegalArgumentException(port + ": expected a port 0..65535");
    }
    host = host.toLowerCase(Locale.ROOT);
  }

  /**
   * Parses {@code host@port}.
   *
   * @throws IllegalArgumentException naming {@code text} and what was expected
   */
  public static PeerAddress parse(String text) {
    Objects.requireNonNull(text, "text == null");
    String s = text.trim();
    int at = s.lastIndexOf('@');
    if (at < 0) {
      throw bad(s, "expected host@port, " + EXAMPLES);
    }
    String host = s.substring(0, at);
    String portText = s.substring(at + 1);
    if (host.startsWith("[") || host.endsWith("]")) {
      boolean closed = host.length() > 2 && host.startsWith("[") && host.endsWith("]");
      host = closed ? host.substring(1, host.length() - 1) : host;
      if (!closed || Addresses.ipv6(host) == null) {
        throw bad(s, "expected an IPv6 address inside [ ], " + EXAMPLES);
      }
    }
    if (!Addresses.isHost(host)) {
      throw bad(s, "expected an IPv4 address, host name or IPv6 address before the last @, "
          + EXAMPLES);
    }
    int port = parsePort(portText);
    if (port < 0) {
      throw bad(s, "expected a port 0..65535 after the last @");
    }
    return new PeerAddress(host, port);
  }

  /**
   * Parses a list of {@code host@port} separated by commas, semicolons or white space. Empty
   * entries are skipped, so a blank text gives an empty list; duplicates are dropped and the
   * first occurrence keeps its place.
   *
   * @return an unmodifiable list
   * @throws IllegalArgumentException naming the first bad entry
   */
  public static List<PeerAddress> parseList(String text) {
    Objects.requireNonNull(text, "text == null");
    if (text.isBlank()) {
      return List.of(); // the default of both keys: no need to compile the separator pattern
    }
    Set<PeerAddress> result = new LinkedHashSet<>();
    for (String entry : text.split("[,;\\s]+")) {
      if (!entry.isEmpty()) {
        result.add(parse(entry));
      }
    }
    return List.copyOf(result);
  }

  /** True when the port is 0, meaning "bind to any free port". */
  public boolean anyPort() {
    return port == 0;
  }

  /**
   * Returns {@code host@port}, with an IPv6 host in brackets ({@code [::1]@10002}), so the result
   * reads unambiguously and {@link #parse} gives back an equal address.
   */
  @Override
  public String toString() {
    return (host.indexOf(':') >= 0 ? "[" + host + "]" : host) + "@" + port;
  }

  /** Parses 0..65535 written in decimal digits only, or returns -1. */
  private static int parsePort(String s) {
    if (s.isEmpty() || s.length() > 5 || !isDigits(s)) {
      return -1;
    }
    int port = Integer.parseInt(s);
    return port <= 65535 ? port : -1;
  }

  private static boolean isDigits(String s) {
    for (int i = 0; i < s.length(); i++) {
      if (s.charAt(i) < '0' || s.charAt(i) > '9') {
        return false;
      }
    }
    return true;
  }

  private static IllegalArgumentException bad(String entry, String expected) {
    return new IllegalArgumentException("'" + entry + "': " + expected);
  }
}
