package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.KEY;
import static dev.trade.internal.discovery.Fixtures.SYSTEM;
import static dev.trade.internal.discovery.Fixtures.address;
import static dev.trade.internal.discovery.Fixtures.announcement;
import static dev.trade.internal.discovery.Fixtures.signed;
import static dev.trade.internal.discovery.Fixtures.utf8;
import static dev.trade.internal.discovery.Fixtures.wire;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The wire format: layout, round trips, and a reason for every packet that is not valid. */
class PacketsTest {
  /** The example of docs/discovery.md, computed there independently (a Python one-off). */
  private static final String DOC_EXAMPLE = "545244410105646961726300000000000000070000018bcfe56800"
      + "0263310361726d0204c0a80114271206fd0000000000000000000000000000012713ada35c2b4abd2b954c"
      + "fb1dc67217f92bfe1c05c921c25749df915e7c6ee6ff9e";

  @Test
  void encodesTheDocumentedExampleByteForByte() throws BadPacketException {
    byte[] key = Packets.deriveKey("diarc", "diarcUser");
    assertEquals("850319c6aa18fbae5dc38a20d3b86eda5e5454f147a46f352255eb649697dfa3",
        HexFormat.of().formatHex(key));
    Announcement a = new Announcement(1, "diarc", "c1", "arm",
        List.of(address("192.168.1.20", 10002), address("fd00::1", 10003)), 7, 1700000000000L);
    byte[] packet = a.encode(key);
    assertEquals(DOC_EXAMPLE, HexFormat.of().formatHex(packet));
    assertEquals(a, Announcement.decode(packet, packet.length, "diarc", key));
  }

  @Test
  void aTemplateFillsInSequenceAndTimestampAndSignsEachPacket() throws BadPacketException {
    Announcement a = new Announcement(1, "diarc", "c1", "arm",
        List.of(address("192.168.1.20", 10002), address("fd00::1", 10003)), 7, 1700000000000L);
    Packets.Template template = new Packets.Template(a);
    Signer signer = new Signer(KEY);
    for (long seq : new long[] {1, 2, Long.MAX_VALUE}) {
      long ts = 1700000000000L + seq % 1000;
      Announcement b = new Announcement(1, "diarc", "c1", "arm", a.addresses(), seq, ts);
      byte[] packet = template.packet(seq, ts, signer);
      assertArrayEquals(b.encode(KEY), packet);
      assertEquals(b, Announcement.decode(packet, packet.length, "diarc", KEY));
    }
  }

  @Test
  void roundTripsEveryField() throws BadPacketException {
    Announcement a = new Announcement(1, "système", "id-é", "Arm 🤖 left",
        List.of(address("10.0.0.5", 1), address("2001:db8::7", 65535)), Long.MAX_VALUE, 0);
    byte[] packet = a.encode(Packets.deriveKey("système", ""));
    assertEquals(a, Announcement.decode(packet, packet.length, "système",
        Packets.deriveKey("système", "")));
  }

  @Test
  void roundTripsTheLargestAnnouncementWithinTheBound() throws BadPacketException {
    List<InetSocketAddress> many = new ArrayList<>();
    for (int i = 0; i < Packets.MAX_ADDRESSES; i++) {
      many.add(address("2001:db8::" + Integer.toHexString(i + 1), 40000 + i));
    }
    Announcement a = new Announcement(1, "s".repeat(64), "i".repeat(64), "n".repeat(255), many,
        1, System.currentTimeMillis());
    byte[] key = Packets.deriveKey("s".repeat(64), "x");
    byte[] packet = a.encode(key);
    assertEquals(744, packet.length);
    assertTrue(packet.length <= Packets.MAX_PACKET);
    assertEquals(a, Announcement.decode(packet, packet.length, "s".repeat(64), key));
  }

  @Test
  void roundTripsNoAddressesAtTheSmallestSize() throws BadPacketException {
    Announcement a = new Announcement(1, "s", "i", "n", List.of(), 1, 5);
    byte[] key = Packets.deriveKey("s", "");
    byte[] packet = a.encode(key);
    assertEquals(Packets.MIN_PACKET, packet.length);
    assertEquals(a, Announcement.decode(packet, packet.length, "s", key));
  }

  @Test
  void decodesOnlyTheGivenLength() throws BadPacketException {
    byte[] packet = announcement("c", 3).encode(KEY);
    byte[] buffer = Arrays.copyOf(packet, Packets.MAX_PACKET + 1);
    assertEquals("c", Announcement.decode(buffer, packet.length, SYSTEM, KEY).containerId());
    assertThrows(IndexOutOfBoundsException.class,
        () -> Announcement.decode(packet, packet.length + 1, SYSTEM, KEY));
  }

  @Test
  void tooShortBelowTheSmallestAnnouncement() {
    byte[] packet = announcement("c", 1).encode(KEY);
    for (int len = 0; len < Packets.MIN_PACKET; len++) {
      assertReason(Reason.TOO_SHORT, packet, len);
    }
  }

  @Test
  void tooLongAboveTheBound() {
    byte[] packet = Arrays.copyOf(announcement("c", 1).encode(KEY), Packets.MAX_PACKET + 1);
    assertReason(Reason.TOO_LONG, packet, packet.length);
  }

  @Test
  void truncatedAtEveryLengthIsRejected() {
    byte[] packet = announcement("c", 1).encode(KEY);
    for (int len = 0; len < packet.length; len++) {
      Reason r = reason(packet, len);
      assertTrue(r == Reason.TOO_SHORT || r == Reason.BAD_HMAC, "length " + len + ": " + r);
    }
  }

  @Test
  void badMagicAndUnsupportedVersionAreReadFromTheHeader() {
    byte[] packet = announcement("c", 1).encode(KEY);
    byte[] magic = packet.clone();
    magic[3] = 'B';
    assertReason(Reason.BAD_MAGIC, magic, magic.length);
    byte[] version = packet.clone();
    version[4] = 2;
    assertEquals("protocol version 2, this container speaks 1",
        assertReason(Reason.UNSUPPORTED_VERSION, version, version.length).getMessage());
  }

  @Test
  void otherSystemIsNamedBeforeTheHmac() {
    Announcement beta = new Announcement(1, "beta", "c", "n", List.of(), 1, 1);
    byte[] packet = beta.encode(Packets.deriveKey("beta", "s3cret"));
    assertEquals("other system id 'beta'",
        assertReason(Reason.FOREIGN_SYSTEM, packet, packet.length).getMessage());
    // A prefix of our id is another id, not ours.
    Announcement alphabet = new Announcement(1, "alphabet", "c", "n", List.of(), 1, 1);
    byte[] longer = alphabet.encode(KEY);
    assertReason(Reason.FOREIGN_SYSTEM, longer, longer.length);
  }

  @Test
  void foreignSystemIdIsMadeSafeForTheLog() {
    byte[] packet = new Announcement(1, "beta", "c", "n", List.of(), 1, 1).encode(KEY);
    packet[7] = '\n';
    assertEquals("other system id 'b?ta'",
        assertReason(Reason.FOREIGN_SYSTEM, packet, packet.length).getMessage());
  }

  @Test
  void wrongCredentialsFailTheHmac() {
    byte[] packet = announcement("c", 1).encode(Packets.deriveKey(SYSTEM, "guess"));
    assertEquals("bad HMAC: wrong CREDENTIALS?",
        assertReason(Reason.BAD_HMAC, packet, packet.length).getMessage());
  }

  @Test
  void everySingleBitFlipIsRejected() {
    byte[] packet = announcement("c", 1).encode(KEY);
    for (int bit = 0; bit < packet.length * 8; bit++) {
      byte[] flipped = packet.clone();
      flipped[bit / 8] ^= (byte) (1 << (bit % 8));
      reason(flipped, flipped.length);
    }
  }

  @Test
  void randomBytesAreRejectedWithAReason() {
    Random random = new Random(20240611L);
    for (int i = 0; i < 20_000; i++) {
      byte[] packet = new byte[random.nextInt(Packets.MAX_PACKET + 100)];
      random.nextBytes(packet);
      if (i % 2 == 0 && packet.length >= 11) {
        // Half of them get our header, so that they reach the HMAC check.
        System.arraycopy(new byte[] {'T', 'R', 'D', 'A', 1, 5, 'a', 'l', 'p', 'h', 'a'}, 0,
            packet, 0, 11);
      }
      reason(packet, packet.length);
    }
  }

  @Test
  void randomSignedBodiesAreMalformedOrValidNeverAnythingElse() {
    Random random = new Random(7L);
    Set<Reason> seen = EnumSet.noneOf(Reason.class);
    for (int i = 0; i < 20_000; i++) {
      byte[] body = new byte[11 + random.nextInt(120)];
      random.nextBytes(body);
      System.arraycopy(new byte[] {'T', 'R', 'D', 'A', 1, 5, 'a', 'l', 'p', 'h', 'a'}, 0, body, 0, 11);
      byte[] packet = Fixtures.sign(body, KEY);
      try {
        Announcement.decode(packet, packet.length, SYSTEM, KEY);
      } catch (BadPacketException e) {
        seen.add(e.reason());
      } catch (RuntimeException e) {
        fail("packet " + HexFormat.of().formatHex(packet) + " threw " + e, e);
      }
    }
    seen.remove(Reason.TOO_SHORT);
    assertEquals(EnumSet.of(Reason.MALFORMED), seen);
  }

  @Test
  void signedButMalformedPacketsSayWhat() {
    byte[] v4 = {10, 0, 0, 1};
    byte[] name = utf8("arm");
    assertMalformed("address 0.0.0.0:4000 is a wildcard: announce the concrete"
        + " addresses of each interface", signed(KEY, 1, "c", name, wire(4, new byte[4], 4000)));
    assertMalformed("address 10.0.0.1:0 has port 0", signed(KEY, 1, "c", name, wire(4, v4, 0)));
    assertMalformed("address family 5", signed(KEY, 1, "c", name, wire(5, v4, 1)));
    assertMalformed("address 224.0.0.1:1 cannot be announced: multicast, or IPv6 link-local",
        signed(KEY, 1, "c", name, wire(4, new byte[] {(byte) 224, 0, 0, 1}, 1)));
    byte[] mapped = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, (byte) 0xff, (byte) 0xff, 10, 0, 0, 1};
    assertMalformed("IPv4-mapped address sent as IPv6", signed(KEY, 1, "c", name, wire(6, mapped, 1)));
    assertMalformed("sequence 0 is not positive", signed(KEY, 0, "c", name));
    assertMalformed("container id is empty", signed(KEY, 1, "", name));
    assertMalformed("container name is not valid UTF-8",
        signed(KEY, 1, "c", new byte[] {(byte) 0xc3, 0x28}));
    assertMalformed("container name contains a control character at index 1",
        signed(KEY, 1, "c", utf8("a\u0007")));
    assertMalformed("a field runs past the end of the packet",
        signed(KEY, 1, "c", name, new byte[] {4, 10, 0}));
    byte[] seventeen = new byte[17 * 7];
    for (int i = 0; i < 17; i++) {
      System.arraycopy(wire(4, v4, 1 + i), 0, seventeen, i * 7, 7);
    }
    assertMalformed("17 addresses, more than 16", withCount(signed(KEY, 1, "c", name, seventeen), 17));
    byte[] body = unsigned(signed(KEY, 1, "c", name));
    byte[] trailing = Arrays.copyOf(body, body.length + 1);
    assertMalformed("1 bytes after the address list", Fixtures.sign(trailing, KEY));
    byte[] overrun = unsigned(signed(KEY, 1, "c", name));
    overrun[6 + 5 + 16] = (byte) 200; // the container id length: beyond the packet
    assertMalformed("container id runs past the end of the packet", Fixtures.sign(overrun, KEY));
  }

  @Test
  void systemIdLengthOutOfBoundsIsMalformedBeforeTheHmac() {
    byte[] packet = announcement("c", 1).encode(KEY);
    packet[5] = 0;
    assertEquals("system id length 0", assertReason(Reason.MALFORMED, packet, packet.length)
        .getMessage());
    packet[5] = 65;
    assertReason(Reason.MALFORMED, packet, packet.length);
  }

  private static byte[] unsigned(byte[] signedPacket) {
    return Arrays.copyOf(signedPacket, signedPacket.length - 32);
  }

  /** Re-signs {@code packet} with its address count byte set to {@code count}. */
  private static byte[] withCount(byte[] packet, int count) {
    byte[] body = unsigned(packet);
    int at = 6 + SYSTEM.length() + 16 + (1 + 1) + (1 + 3); // header, numbers, "c", "arm"
    body[at] = (byte) count;
    return Fixtures.sign(body, KEY);
  }

  private static void assertMalformed(String message, byte[] packet) {
    assertEquals(message, assertReason(Reason.MALFORMED, packet, packet.length).getMessage());
  }

  private static BadPacketException assertReason(Reason expected, byte[] packet, int len) {
    BadPacketException e = assertThrows(BadPacketException.class,
        () -> Announcement.decode(packet, len, SYSTEM, KEY));
    assertEquals(expected, e.reason(), e.getMessage());
    return e;
  }

  /** The reason {@code packet} is rejected; fails if it is accepted or throws anything else. */
  private static Reason reason(byte[] packet, int len) {
    try {
      Announcement a = Announcement.decode(packet, len, SYSTEM, KEY);
      throw new AssertionError("accepted " + a + " from " + HexFormat.of().formatHex(packet, 0, len));
    } catch (BadPacketException e) {
      return e.reason();
    } catch (RuntimeException e) {
      throw new AssertionError("threw " + e + " for " + HexFormat.of().formatHex(packet, 0, len), e);
    }
  }
}
