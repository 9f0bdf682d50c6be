package dev.trade.internal.discovery;

import java.security.GeneralSecurityException;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * HMAC-SHA256 with one system's key, set up once. {@code Mac.getInstance} walks the JCA provider
 * list and {@code init} hashes the key pads: together more than the HMAC of a packet itself, and a
 * container in a system of 100 verifies dozens of announcements a second while they start.
 *
 * <p>Not thread-safe: each sending or receiving thread keeps its own.
 */
final class Signer {
  private final Mac mac;

  /** @param key from {@link Packets#deriveKey(String, String)} */
  Signer(byte[] key) {
    try {
      mac = Mac.getInstance("HmacSHA256");
      mac.init(new SecretKeySpec(key, "HmacSHA256"));
    } catch (GeneralSecurityException e) {
      throw new AssertionError("every JDK has HmacSHA256", e);
    }
  }

  /** The HMAC of the first {@code len} bytes of {@code data}. */
  byte[] sign(byte[] data, int len) {
    mac.update(data, 0, len);
    return mac.doFinal(); // and ready for the next
  }
}
