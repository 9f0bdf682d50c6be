package dev.trade.internal.crypto;

import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;

/**
 * HMAC-SHA256 (RFC 2104) over the JDK's SHA-256 {@link MessageDigest}: the same bytes as {@code
 * javax.crypto.Mac.getInstance("HmacSHA256")}, built the way the JDK builds that Mac (its {@code
 * HmacCore} also runs a {@code MessageDigest} over the key's inner and outer pads).
 *
 * <p>Why not that {@code Mac}: its first use in a JVM sets up {@code javax.crypto} (the JCE reads
 * the crypto policy and checks its providers), 40-59 ms on the benchmark machine even after
 * the JCA itself is up, and a starting container signs its first announcement and proves its
 * credentials on its first link before anything else can reach it. A {@code MessageDigest} costs
 * under 1 ms once the JCA is up, which the container's id (a {@code SecureRandom}) needs anyway.
 *
 * <p>Use as a {@code Mac}: {@link #update} the message, then {@link #doFinal}, which also readies
 * this instance for the next message with the same key. Not thread-safe: one thread at a time.
 */
public final class HmacSha256 {
  private static final int BLOCK = 64; // SHA-256's block size

  private final MessageDigest digest;
  private final byte[] innerPad = new byte[BLOCK];
  private final byte[] outerPad = new byte[BLOCK];
  /** Whether {@link #innerPad} went into {@link #digest} for the message under way. */
  private boolean started;

  /** @param key any length; one longer than SHA-256's block is hashed first, as RFC 2104 says */
  public HmacSha256(byte[] key) {
    digest = sha256();
    byte[] k = key.length > BLOCK ? digest.digest(key) : key;
    for (int i = 0; i < BLOCK; i++) {
      byte b = i < k.length ? k[i] : 0;
      innerPad[i] = (byte) (b ^ 0x36);
      outerPad[i] = (byte) (b ^ 0x5c);
    }
  }

  /** The HMAC of the concatenated {@code parts} under {@code key}. */
  public static byte[] of(byte[] key, byte[]... parts) {
    HmacSha256 mac = new HmacSha256(key);
    for (byte[] p : parts) {
      mac.update(p);
    }
    return mac.doFinal();
  }

  /** Adds {@code b} to the message. */
  public HmacSha256 update(byte b) {
    start().update(b);
    return this;
  }

  /** Adds {@code bytes} to the message. */
  public HmacSha256 update(byte[] bytes) {
    return update(bytes, 0, bytes.length);
  }

  /** Adds {@code len} bytes of {@code bytes} from {@code off} to the message. */
  public HmacSha256 update(byte[] bytes, int off, int len) {
    start().update(bytes, off, len);
    return this;
  }

  /** The HMAC of the message added since the last {@code doFinal}; then starts a new message. */
  public byte[] doFinal() {
    byte[] inner = start().digest();
    started = false;
    digest.update(outerPad);
    digest.update(inner);
    return digest.digest();
  }

  private MessageDigest start() {
    if (!started) {
      digest.update(innerPad);
      started = true;
    }
    return digest;
  }

  private static MessageDigest sha256() {
    try {
      return MessageDigest.getInstance("SHA-256");
    } catch (NoSuchAlgorithmException e) {
      throw new AssertionError("every JDK has SHA-256", e);
    }
  }
}
