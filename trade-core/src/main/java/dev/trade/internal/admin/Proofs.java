package dev.trade.internal.admin;

import dev.trade.internal.crypto.HmacSha256;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The proof a caller puts in a CALL's context under {@link #KEY}: it shows that the caller knows
 * a principal's secret without sending it (docs/protocol.md, "Proof of a principal"). The value
 * is the text {@code 1 <principal> <time> <nonce> <mac>}: version 1, the principal's name, the
 * caller's clock in milliseconds since the epoch (decimal), a 16-byte nonce and the HMAC-SHA256
 * as lower-case hex, where
 *
 * <pre>
 * key = HMAC-SHA256(UTF-8(secret), UTF-8("trade.auth.key.1\n" + principal))
 * mac = HMAC-SHA256(key, UTF-8("trade.auth.1\n" + principal + "\n" + source + "\n"
 *                              + destination + "\n" + serviceId + "\n" + time + "\n" + nonce))
 * </pre>
 *
 * with {@code source} and {@code destination} the calling and providing containers' ids (UUID
 * text, lower case) and {@code serviceId} the service's id in decimal. Safe for concurrent use.
 */
public final class Proofs {
  /** The reserved call context key that carries a proof. */
  public static final String KEY = "trade.auth";
  static final String VERSION = "1";
  private static final HexFormat HEX = HexFormat.of();

  /** Unique per JVM: a random prefix and a counter, so that no two proofs share a nonce. */
  private static final byte[] NONCE_PREFIX = new SecureRandom().generateSeed(8);
  private static final AtomicLong NONCE_COUNTER = new AtomicLong();

  private Proofs() {}

  /** The key derived from a principal's secret: the only form of it a MAC is made with. */
  public static byte[] key(String principal, String secret) {
    return HmacSha256.of(secret.getBytes(StandardCharsets.UTF_8),
        ("trade.auth.key.1\n" + principal).getBytes(StandardCharsets.UTF_8));
  }

  static byte[] mac(byte[] key, String principal, String source, String destination,
      long serviceId, long timeMillis, String nonce) {
    return HmacSha256.of(key, ("trade.auth.1\n" + principal + "\n" + source + "\n" + destination
        + "\n" + serviceId + "\n" + timeMillis + "\n" + nonce).getBytes(StandardCharsets.UTF_8));
  }

  /** A fresh nonce: 32 hex digits, never repeated in this JVM. */
  static String nonce() {
    byte[] n = new byte[16];
    System.arraycopy(NONCE_PREFIX, 0, n, 0, 8);
    long c = NONCE_COUNTER.incrementAndGet();
    for (int i = 0; i < 8; i++) {
      n[15 - i] = (byte) (c >>> (8 * i));
    }
    return HEX.formatHex(n);
  }

  /**
   * The proof of {@code credentials} for one call.
   *
   * @param nowMillis the caller's clock, milliseconds since the epoch
   */
  public static String sign(Credentials credentials, String source, String destination,
      long serviceId, long nowMillis) {
    return sign(credentials.principal(), key(credentials.principal(), credentials.secret()), source,
        destination, serviceId, nowMillis, nonce());
  }

  /** The proof of {@code principal}, whose key is {@code key}, with this time and nonce. */
  public static String sign(String principal, byte[] key, String source, String destination,
      long serviceId, long timeMillis, String nonce) {
    return VERSION + " " + principal + " " + timeMillis + " " + nonce + " "
        + HEX.formatHex(mac(key, principal, source, destination, serviceId, timeMillis, nonce));
  }

  /** A proof as read from a context, fields checked for form only. */
  record Parsed(String principal, long timeMillis, String nonce, byte[] mac) {}

  /** Parses a proof's text; null if it is not of the form above (then it is refused as forged). */
  static Parsed parse(String text) {
    String[] f = text.split(" ", -1);
    if (f.length != 5 || !f[0].equals(VERSION) || !AccessFile.NAME.matcher(f[1]).matches()
        || f[3].length() != 32 || f[4].length() != 64 || f[2].isEmpty() || f[2].length() > 19) {
      return null;
    }
    try {
      long time = Long.parseLong(f[2]);
      HEX.parseHex(f[3]);
      return new Parsed(f[1], time, f[3], HEX.parseHex(f[4]));
    } catch (IllegalArgumentException e) {
      return null;
    }
  }

  /** Whether {@code p}'s MAC is the one {@code key} gives for this call (constant time). */
  static boolean verify(Parsed p, byte[] key, String source, String destination, long serviceId) {
    return MessageDigest.isEqual(p.mac(),
        mac(key, p.principal(), source, destination, serviceId, p.timeMillis(), p.nonce()));
  }
}
