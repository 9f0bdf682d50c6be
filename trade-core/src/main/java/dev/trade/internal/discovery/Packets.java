package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.BufferUnderflowException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;

/**
 * The wire format of announcements: fixed layout, big-endian, never serialized objects.
 *
 * <pre>
 *   offset   size  field
 *   0        4     magic "TRDA" (54 52 44 41)
 *   4        1     protocol version: 1
 *   5        1     S: system id length, 1..64
 *   6        S     system id, UTF-8                 -- end of the header read before the HMAC
 *   6+S      8     sequence, signed, &gt; 0
 *   14+S     8     timestamp, ms since the epoch, signed, &gt;= 0
 *   22+S     1     C: container id length, 1..64
 *            C     container id, UTF-8
 *            1     N: container name length, 1..255
 *            N     container name, UTF-8
 *            1     A: address count, 0..16
 *            A x   family (1 byte: 4 or 6), address (4 or 16 bytes), port (2 bytes, 1..65535)
 *   len-32   32    HMAC-SHA256(key, bytes 0 .. len-33)
 * </pre>
 *
 * <p>{@code key = SHA-256("TRADE-discovery-v1" || UTF-8(systemId) || 0x00 || UTF-8(credentials))}.
 * A receiver checks, in order: the length (at most {@value #MAX_PACKET} bytes, at least
 * {@value #MIN_PACKET}), magic, version, the system id, the HMAC; only then does it read the rest,
 * and every length is checked against what is left before anything is allocated. Nothing follows
 * the address list but the HMAC. Stateless; safe for concurrent use.
 */
final class Packets {
  static final byte[] MAGIC = {'T', 'R', 'D', 'A'};
  static final int VERSION = 1;
  static final int MAX_SYSTEM_ID = 64;
  static final int MAX_CONTAINER_ID = 64;
  static final int MAX_CONTAINER_NAME = 255;
  static final int MAX_ADDRESSES = 16;
  static final int MAC_LENGTH = 32;
  /** Fits one unfragmented datagram even on IPv6's minimum MTU (1280 less headers). */
  static final int MAX_PACKET = 1200;
  /** Header with a 1-byte system id, both numbers, 1-byte id and name, no address, the HMAC. */
  static final int MIN_PACKET = 6 + 1 + 16 + 2 + 2 + 1 + MAC_LENGTH;
  private static final int HEADER = 6;
  private static final byte[] KEY_LABEL = "TRADE-discovery-v1".getBytes(StandardCharsets.US_ASCII);

  private Packets() {}

  /**
   * The HMAC key of a system: anyone who knows both the system id and the credentials can announce
   * in it. Empty credentials are allowed; the HMAC then only keeps systems apart and catches
   * corruption, it does not keep anyone out.
   *
   * @throws IllegalArgumentException if {@code systemId} is not a valid system id
   */
  static byte[] deriveKey(String systemId, String credentials) {
    Announcement.checkText(systemId, "system id", MAX_SYSTEM_ID);
    Objects.requireNonNull(credentials, "credentials == null");
    try {
      MessageDigest sha = MessageDigest.getInstance("SHA-256");
      sha.update(KEY_LABEL);
      // The system id has no control characters, so the 0x00 separator is unambiguous.
      sha.update(systemId.getBytes(StandardCharsets.UTF_8));
      sha.update((byte) 0);
      sha.update(credentials.getBytes(StandardCharsets.UTF_8));
      return sha.digest();
    } catch (GeneralSecurityException e) {
      throw new AssertionError("every JDK has SHA-256", e);
    }
  }

  static byte[] encode(Announcement a, byte[] key) {
    return encode(a, new Signer(key));
  }

  static byte[] encode(Announcement a, Signer signer) {
    return new Template(a).packet(a.sequence(), a.timestampMillis(), signer);
  }

  /**
   * The bytes of one container's announcement but for its sequence number, timestamp and HMAC,
   * which {@link #packet} fills in. A container sends the same announcement again and again (in
   * its start burst, every interval, to each newcomer: about a hundred answers while a system of
   * 100 starts), so its text is checked and encoded once, not per packet. Immutable.
   */
  static final class Template {
    private final byte[] unsigned;
    private final int sequenceAt;

    /** @param a checked by its constructor; its sequence and timestamp are not used */
    Template(Announcement a) {
      ByteBuffer b = ByteBuffer.allocate(MAX_PACKET);
      b.put(MAGIC).put((byte) VERSION);
      putText(b, a.systemId());
      sequenceAt = b.position();
      b.putLong(0).putLong(0);
      putText(b, a.containerId());
      putText(b, a.containerName());
      b.put((byte) a.addresses().size());
      for (InetSocketAddress s : a.addresses()) {
        byte[] raw = s.getAddress().getAddress();
        b.put((byte) (raw.length == 4 ? 4 : 6)).put(raw).putShort((short) s.getPort());
      }
      unsigned = Arrays.copyOf(b.array(), b.position());
    }

    /** The signed packet with {@code sequence} and {@code timestampMillis}. */
    byte[] packet(long sequence, long timestampMillis, Signer signer) {
      byte[] packet = Arrays.copyOf(unsigned, unsigned.length + MAC_LENGTH);
      ByteBuffer.wrap(packet).putLong(sequenceAt, sequence).putLong(sequenceAt + 8, timestampMillis);
      System.arraycopy(signer.sign(packet, unsigned.length), 0, packet, unsigned.length, MAC_LENGTH);
      return packet;
    }
  }

  /**
   * Checks and reads the first {@code len} bytes of {@code packet}.
   *
   * @param systemId this container's system id; packets of others are {@link Reason#FOREIGN_SYSTEM}
   * @param key this system's key, from {@link #deriveKey(String, String)}
   * @return the announcement, valid as its constructor defines; the caller still has to check
   *     replays and whether it is our own
   * @throws BadPacketException for every packet that is not a well-formed announcement of
   *     {@code systemId} signed with {@code key}; never any other exception
   * @throws IndexOutOfBoundsException if {@code len} is negative or beyond {@code packet}
   */
  static Announcement decode(byte[] packet, int len, String systemId, byte[] key)
      throws BadPacketException {
    return decode(packet, len, systemId, new Signer(key));
  }

  /** As {@link #decode(byte[], int, String, byte[])}, with the key's {@link Signer}. */
  static Announcement decode(byte[] packet, int len, String systemId, Signer signer)
      throws BadPacketException {
    Objects.checkFromIndexSize(0, len, packet.length);
    if (len > MAX_PACKET) {
      throw new BadPacketException(Reason.TOO_LONG, len + " bytes, more than " + MAX_PACKET);
    }
    if (len < MIN_PACKET) {
      throw new BadPacketException(Reason.TOO_SHORT, len + " bytes, less than " + MIN_PACKET);
    }
    if (!Arrays.equals(packet, 0, MAGIC.length, MAGIC, 0, MAGIC.length)) {
      throw new BadPacketException(Reason.BAD_MAGIC, "no TRADE magic bytes");
    }
    int version = packet[4] & 0xff;
    if (version != VERSION) {
      throw new BadPacketException(Reason.UNSUPPORTED_VERSION, "protocol version " + version
          + ", this container speaks " + VERSION);
    }
    int s = packet[5] & 0xff;
    if (s == 0 || s > MAX_SYSTEM_ID) {
      throw new BadPacketException(Reason.MALFORMED, "system id length " + s);
    }
    if (HEADER + s + MAC_LENGTH > len) {
      throw new BadPacketException(Reason.TOO_SHORT, len + " bytes, less than its header");
    }
    byte[] ours = systemId.getBytes(StandardCharsets.UTF_8);
    if (!Arrays.equals(packet, HEADER, HEADER + s, ours, 0, ours.length)) {
      throw new BadPacketException(Reason.FOREIGN_SYSTEM,
          "other system id '" + printable(packet, HEADER, s) + "'");
    }
    int signed = len - MAC_LENGTH;
    byte[] expected = signer.sign(packet, signed);
    // Constant time: a timing difference would let an attacker guess the HMAC byte by byte.
    if (!MessageDigest.isEqual(expected, Arrays.copyOfRange(packet, signed, len))) {
      throw new BadPacketException(Reason.BAD_HMAC, "bad HMAC: wrong CREDENTIALS?");
    }
    return parseBody(ByteBuffer.wrap(packet, HEADER + s, signed - HEADER - s), systemId);
  }

  private static Announcement parseBody(ByteBuffer b, String systemId) throws BadPacketException {
    try {
      long sequence = b.getLong();
      long timestamp = b.getLong();
      String containerId = getText(b, "container id");
      String containerName = getText(b, "container name");
      int count = b.get() & 0xff;
      if (count > MAX_ADDRESSES) {
        throw new BadPacketException(Reason.MALFORMED, count + " addresses, more than "
            + MAX_ADDRESSES);
      }
      List<InetSocketAddress> addresses = new ArrayList<>(count);
      for (int i = 0; i < count; i++) {
        addresses.add(getAddress(b));
      }
      if (b.hasRemaining()) {
        throw new BadPacketException(Reason.MALFORMED, b.remaining()
            + " bytes after the address list");
      }
      return new Announcement(VERSION, systemId, containerId, containerName, addresses,
          sequence, timestamp);
    } catch (BufferUnderflowException e) {
      throw new BadPacketException(Reason.MALFORMED, "a field runs past the end of the packet");
    } catch (IllegalArgumentException e) {
      throw new BadPacketException(Reason.MALFORMED, e.getMessage());
    }
  }

  private static InetSocketAddress getAddress(ByteBuffer b) throws BadPacketException {
    int family = b.get() & 0xff;
    if (family != 4 && family != 6) {
      throw new BadPacketException(Reason.MALFORMED, "address family " + family);
    }
    byte[] raw = new byte[family == 4 ? 4 : 16];
    b.get(raw);
    int port = b.getShort() & 0xffff;
    InetAddress address;
    try {
      address = InetAddress.getByAddress(raw);
    } catch (UnknownHostException e) {
      throw new AssertionError("4 and 16 bytes are valid lengths", e);
    }
    // The JDK turns an IPv4-mapped IPv6 address into an IPv4 one: one address, one encoding.
    if (family == 6 && address instanceof Inet4Address) {
      throw new BadPacketException(Reason.MALFORMED, "IPv4-mapped address sent as IPv6");
    }
    return new InetSocketAddress(address, port);
  }

  private static String getText(ByteBuffer b, String field) throws BadPacketException {
    int n = b.get() & 0xff;
    if (n > b.remaining()) {
      throw new BadPacketException(Reason.MALFORMED, field + " runs past the end of the packet");
    }
    try {
      String s = StandardCharsets.UTF_8.newDecoder()
          .onMalformedInput(CodingErrorAction.REPORT)
          .onUnmappableCharacter(CodingErrorAction.REPORT)
          .decode(b.slice(b.position(), n)).toString();
      b.position(b.position() + n);
      return s;
    } catch (CharacterCodingException e) {
      throw new BadPacketException(Reason.MALFORMED, field + " is not valid UTF-8");
    }
  }

  private static void putText(ByteBuffer b, String s) {
    byte[] bytes = s.getBytes(StandardCharsets.UTF_8);
    b.put((byte) bytes.length).put(bytes);
  }

  /** Unauthenticated text from a packet, made safe for a log line. */
  static String printable(byte[] bytes, int offset, int len) {
    String s = new String(bytes, offset, len, StandardCharsets.UTF_8);
    StringBuilder out = new StringBuilder(s.length());
    s.codePoints().forEach(c -> out.appendCodePoint(Character.isISOControl(c) ? '?' : c));
    return out.toString();
  }
}
