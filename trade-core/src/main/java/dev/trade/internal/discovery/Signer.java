package dev.trade.internal.discovery;

import java.security.GeneralSecurityException;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * HMAC-SHA256 with one system's key, set up once. {@code Mac.getInstance} walks the JCA provider
 * list and {@code init} hashes the key pads: together more than the HMAC of a packet itself, and a
 * container in a system of 100 verifies dozens of announcements a second while they start. It is
 * set up at the first packet, on the thread that sends or receives, not by the constructor: the
 * JCA's first use in a JVM takes tens of milliseconds that a starting container need not wait for.
 *
 * <p>Not thread-safe: each sending or receiving thread keeps its own.
 */
final class Signer {
  private final byte[] key;
  private Mac mac;

  /** @param key from {@link Packets#deriveKey(String, String)} */
  Signer(byte[] key) {
    this.key = key.clone();
  }

  /** The HMAC of the first {@code len} bytes of {@code data}. */
  byte[] sign(byte[] data, int len) {
    if (mac == null) {
      try {
        Mac m = Mac.getInstance("HmacSHA256");
        m.init(new SecretKeySpec(key, "HmacSHA256"));
        mac = m;
      } catch (GeneralSecurityException e) {
        throw new AssertionError("every JDK has HmacSHA256", e);
      }
    }
    mac.update(data, 0, len);
    return mac.doFinal(); // and ready for the next
  }
}
