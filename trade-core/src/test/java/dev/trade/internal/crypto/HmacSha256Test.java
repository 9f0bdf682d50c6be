package dev.trade.internal.crypto;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.Random;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import org.junit.jupiter.api.Test;

class HmacSha256Test {
  private static final HexFormat HEX = HexFormat.of();

  /** RFC 4231, test cases 1, 2, 3, 6 and 7 (6 and 7 with a key longer than a block). */
  @Test
  void matchesTheTestVectorsOfRfc4231() {
    assertMac("b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7",
        filled(20, 0x0b), ascii("Hi There"));
    assertMac("5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843",
        ascii("Jefe"), ascii("what do ya want for nothing?"));
    assertMac("773ea91e36800e46854db8ebd09181a72959098b3ef8c122d9635514ced565fe",
        filled(20, 0xaa), filled(50, 0xdd));
    assertMac("60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54",
        filled(131, 0xaa), ascii("Test Using Larger Than Block-Size Key - Hash Key First"));
    assertMac("9b09ffa71b942fcb27635fbcd5b0e944bfdc63644f0713938a7f51535c3a35e2",
        filled(131, 0xaa), ascii("This is a test using a larger than block-size key and a larger"
            + " than block-size data. The key needs to be hashed before being used by the HMAC"
            + " algorithm."));
  }

  /**
   * The same bytes as the JDK's {@code Mac} for keys and messages of every length around the
   * block size, fed whole, in pieces and byte by byte, and for message after message on one
   * instance (each {@code doFinal} starts the next).
   */
  @Test
  void agreesWithTheJdksMacWhateverTheLengthsAndHowTheMessageIsFed() throws Exception {
    Random random = new Random(42);
    for (int keyLength : new int[] {1, 31, 32, 63, 64, 65, 200}) {
      byte[] key = new byte[keyLength];
      random.nextBytes(key);
      Mac jdk = Mac.getInstance("HmacSHA256");
      jdk.init(new SecretKeySpec(key, "HmacSHA256"));
      HmacSha256 ours = new HmacSha256(key);
      for (int length : new int[] {0, 1, 55, 56, 63, 64, 65, 119, 1000}) {
        byte[] message = new byte[length];
        random.nextBytes(message);
        byte[] expected = jdk.doFinal(message);
        assertArrayEquals(expected, ours.update(message).doFinal(), "whole, key " + keyLength);
        int cut = length / 3;
        ours.update(message, 0, cut).update(Arrays.copyOfRange(message, cut, length));
        assertArrayEquals(expected, ours.doFinal(), "in two pieces");
        for (byte b : message) {
          ours.update(b);
        }
        assertArrayEquals(expected, ours.doFinal(), "byte by byte");
        assertEquals(32, expected.length);
      }
    }
  }

  @Test
  void ofJoinsThePartsIntoOneMessage() {
    byte[] key = ascii("key");
    assertArrayEquals(new HmacSha256(key).update(ascii("part one, part two")).doFinal(),
        HmacSha256.of(key, ascii("part one, "), ascii("part two")));
  }

  private static void assertMac(String expectedHex, byte[] key, byte[] message) {
    assertEquals(expectedHex, HEX.formatHex(HmacSha256.of(key, message)));
  }

  private static byte[] filled(int length, int value) {
    byte[] b = new byte[length];
    Arrays.fill(b, (byte) value);
    return b;
  }

  private static byte[] ascii(String s) {
    return s.getBytes(StandardCharsets.US_ASCII);
  }
}
