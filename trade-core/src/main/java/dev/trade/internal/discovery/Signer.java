package dev.trade.internal.discovery;

import dev.trade.internal.crypto.HmacSha256;

/**
 * HMAC-SHA256 with one system's key, set up once (the digest's provider lookup and the key's
 * pads), since a container in a system of 100 verifies dozens of announcements a second while they
 * start. It is set up at the first packet, on the thread that sends or receives, not by the
 * constructor: the JCA's first use in a JVM takes tens of milliseconds that a starting container
 * need not wait for.
 *
 * <p>Not thread-safe: each sending or receiving thread keeps its own.
 */
final class Signer {
  private final byte[] key;
  private HmacSha256 mac;

  /** @param key from {@link Packets#deriveKey(String, String)} */
  Signer(byte[] key) {
    this.key = key.clone();
  }

  /** The HMAC of the first {@code len} bytes of {@code data}. */
  byte[] sign(byte[] data, int len) {
    if (mac == null) {
      mac = new HmacSha256(key);
    }
    return mac.update(data, 0, len).doFinal(); // and ready for the next
  }
}
