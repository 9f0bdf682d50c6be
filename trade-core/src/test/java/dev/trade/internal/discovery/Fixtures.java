package dev.trade.internal.discovery;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.List;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/** Announcements, keys and hand-made packets for the discovery tests. */
final class Fixtures {
  static final String SYSTEM = "alpha";
  static final byte[] KEY = Packets.deriveKey(SYSTEM, "s3cret");

  private Fixtures() {}

  static InetSocketAddress address(String literal, int port) {
    try {
      return new InetSocketAddress(InetAddress.getByName(literal), port);
    } catch (UnknownHostException e) {
      throw new AssertionError(e);
    }
  }

  static Announcement announcement(String containerId, long sequence) {
    return announcement(containerId, sequence, System.currentTimeMillis());
  }

  static Announcement announcement(String containerId, long sequence, long timestampMillis) {
    return new Announcement(1, SYSTEM, containerId, "robot-" + containerId,
        List.of(address("127.0.0.1", 4000), address("::1", 4001)), sequence, timestampMillis);
  }

  /**
   * The bytes of an announcement of {@link #SYSTEM}, written field by field by the test itself
   * (not by {@link Packets}), then signed with {@code key}: for packets the encoder refuses to make.
   */
  static byte[] signed(byte[] key, long sequence, String containerId, byte[] name, byte[]... addresses) {
    ByteBuffer b = ByteBuffer.allocate(4000);
    b.put("TRDA".getBytes(StandardCharsets.US_ASCII)).put((byte) 1);
    text(b, SYSTEM.getBytes(StandardCharsets.UTF_8));
    b.putLong(sequence).putLong(System.currentTimeMillis());
    text(b, containerId.getBytes(StandardCharsets.UTF_8));
    text(b, name);
    b.put((byte) addresses.length);
    for (byte[] a : addresses) {
      b.put(a);
    }
    return sign(Arrays.copyOf(b.array(), b.position()), key);
  }

  /** {@code body} followed by its HMAC-SHA256, computed here independently of the code under test. */
  static byte[] sign(byte[] body, byte[] key) {
    try {
      Mac mac = Mac.getInstance("HmacSHA256");
      mac.init(new SecretKeySpec(key, "HmacSHA256"));
      byte[] out = Arrays.copyOf(body, body.length + 32);
      System.arraycopy(mac.doFinal(body), 0, out, body.length, 32);
      return out;
    } catch (GeneralSecurityException e) {
      throw new AssertionError(e);
    }
  }

  /** One wire-format address: family, raw bytes, port. */
  static byte[] wire(int family, byte[] raw, int port) {
    return ByteBuffer.allocate(1 + raw.length + 2).put((byte) family).put(raw)
        .putShort((short) port).array();
  }

  static byte[] utf8(String s) {
    return s.getBytes(StandardCharsets.UTF_8);
  }

  private static void text(ByteBuffer b, byte[] bytes) {
    b.put((byte) bytes.length).put(bytes);
  }
}
