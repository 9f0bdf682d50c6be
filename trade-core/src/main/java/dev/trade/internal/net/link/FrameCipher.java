package dev.trade.internal.net.link;

import dev.trade.internal.crypto.HmacSha256;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.util.UUID;
import javax.crypto.Cipher;
import javax.crypto.spec.GCMParameterSpec;
import javax.crypto.spec.SecretKeySpec;

/**
 * Frame encryption for {@code USEENCRYPTION=true}: AES-256-GCM with one key per direction, derived
 * from the credentials-based key and both handshake nonces, so every connection has fresh keys and
 * the secret itself never travels. The GCM nonce is a per-direction frame counter; a frame that is
 * altered, replayed, reordered or dropped fails authentication and closes the link.
 *
 * <p>Each direction is used by one thread at a time (the link's writer, its reader), handed over
 * under the link's lock: not thread-safe on its own.
 */
final class FrameCipher {
  static final int TAG_BYTES = 16;

  private final Cipher sealer;
  private final Cipher opener;
  private final SecretKeySpec sendKey;
  private final SecretKeySpec receiveKey;
  private long sent;
  private long received;

  FrameCipher(byte[] key, UUID sender, UUID receiver, byte[] senderNonce, byte[] receiverNonce) {
    try {
      this.sendKey = new SecretKeySpec(derive(key, sender, receiver, senderNonce, receiverNonce), "AES");
      this.receiveKey = new SecretKeySpec(derive(key, receiver, sender, receiverNonce, senderNonce), "AES");
      this.sealer = Cipher.getInstance("AES/GCM/NoPadding");
      this.opener = Cipher.getInstance("AES/GCM/NoPadding");
    } catch (GeneralSecurityException e) {
      throw new IllegalStateException("AES/GCM is part of every JDK", e);
    }
  }

  /**
   * {@code HMAC-SHA256(key, "TRADE-enc-v1" | from | to | fromNonce | toNonce)}: the key of the
   * direction {@code from → to}.
   */
  static byte[] derive(byte[] key, UUID from, UUID to, byte[] fromNonce, byte[] toNonce) {
    return HmacSha256.of(key, "TRADE-enc-v1".getBytes(StandardCharsets.US_ASCII),
        ByteBuffer.allocate(32).putLong(from.getMostSignificantBits())
            .putLong(from.getLeastSignificantBits()).putLong(to.getMostSignificantBits())
            .putLong(to.getLeastSignificantBits()).array(),
        fromNonce, toNonce);
  }

  /** A plain frame (u32 length | body) as an encrypted one (u32 length | sealed body | tag). */
  byte[] seal(byte[] frame) {
    try {
      sealer.init(Cipher.ENCRYPT_MODE, sendKey, nonce(sent++));
      byte[] out = new byte[frame.length + TAG_BYTES];
      int n = sealer.doFinal(frame, 4, frame.length - 4, out, 4);
      ByteBuffer.wrap(out).putInt(0, n);
      return out;
    } catch (GeneralSecurityException e) {
      throw new IllegalStateException("cannot encrypt a frame", e);
    }
  }

  /**
   * The body of a received encrypted frame, decrypted.
   *
   * @throws GeneralSecurityException when the frame was altered, replayed or is out of order
   */
  byte[] open(byte[] sealed) throws GeneralSecurityException {
    opener.init(Cipher.DECRYPT_MODE, receiveKey, nonce(received++));
    return opener.doFinal(sealed);
  }

  private static GCMParameterSpec nonce(long counter) {
    return new GCMParameterSpec(TAG_BYTES * 8, ByteBuffer.allocate(12).putLong(4, counter).array());
  }
}
