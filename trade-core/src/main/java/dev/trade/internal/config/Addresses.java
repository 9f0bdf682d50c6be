package dev.trade.internal.config;

import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.regex.Pattern;

/**
 * Syntax checks for host names and IP literals that never touch the network.
 *
 * <p>{@link InetAddress#getByName} falls back to a DNS lookup for anything it does not recognise as
 * a literal, so a typo in a settings file could stall startup on a resolver timeout. Everything
 * here only looks at the text; whether a name resolves is for the networking code to find out when
 * it connects. Stateless and safe for concurrent use.
 */
final class Addresses {
  private static final String OCTET = "(25[0-5]|2[0-4]\\d|1\\d\\d|[1-9]?\\d)";
  // Leading zeros are refused: some resolvers read "010" as octal 8, the JDK as decimal 10.
  private static final Pattern IPV4 = Pattern.compile(OCTET + "(\\." + OCTET + "){3}");
  private static final Pattern DIGITS_AND_DOTS = Pattern.compile("[0-9.]+");
  private static final Pattern IPV6_CHARS = Pattern.compile("[0-9A-Fa-f:.]+");
  private static final Pattern ZONE = Pattern.compile("[A-Za-z0-9_.-]+");
  // RFC 1123 labels, plus '_' because container runtimes hand out such names
  // (e.g. compose services).
  private static final Pattern LABEL =
      Pattern.compile("[A-Za-z0-9_]([A-Za-z0-9_-]{0,61}[A-Za-z0-9_])?");

  private Addresses() {}

  /** True for a dotted-quad IPv4 literal such as {@code 127.0.0.1}. */
  static boolean isIpv4(String s) {
    return IPV4.matcher(s).matches();
  }

  /**
   * Parses an IPv6 literal without brackets, optionally with a {@code %zone}.
   *
   * @return the address, or null if {@code s} is not an IPv6 literal
   */
  static InetAddress ipv6(String s) {
    int percent = s.indexOf('%');
    String address = percent < 0 ? s : s.substring(0, percent);
    if (percent >= 0 && !ZONE.matcher(s.substring(percent + 1)).matches()) {
      return null;
    }
    if (address.indexOf(':') < 0 || !IPV6_CHARS.matcher(address).matches()) {
      return null;
    }
    try {
      // In brackets the JDK treats the text as an IPv6 literal only and never asks DNS. The zone
      // is left out because the JDK would look the interface up on this machine.
      return InetAddress.getByName("[" + address + "]");
    } catch (UnknownHostException e) {
      return null;
    }
  }

  /** Parses an IPv4 or IPv6 literal (no brackets), or returns null. */
  static InetAddress literal(String s) {
    if (isIpv4(s)) {
      try {
        return InetAddress.getByName(s); // a literal: no lookup
      } catch (UnknownHostException e) {
        throw new AssertionError("IPv4 literal rejected: " + s, e);
      }
    }
    return ipv6(s);
  }

  /**
   * True for an IPv4 literal, an IPv6 literal (no brackets) or a syntactically valid host name.
   * A name made only of digits and dots must be a valid IPv4 literal, so {@code 300.1.1.1} or
   * {@code 10.1} are refused rather than sent to a resolver.
   */
  static boolean isHost(String s) {
    if (s.isEmpty() || s.length() > 253) {
      return false;
    }
    if (DIGITS_AND_DOTS.matcher(s).matches()) {
      return isIpv4(s);
    }
    if (s.indexOf(':') >= 0) {
      return ipv6(s) != null;
    }
    for (String label : s.split("\\.", -1)) {
      if (!LABEL.matcher(label).matches()) {
        return false;
      }
    }
    return true;
  }
}
