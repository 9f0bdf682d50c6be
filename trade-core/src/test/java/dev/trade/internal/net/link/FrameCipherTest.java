package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.UUID;
import org.junit.jupiter.api.Test;

class FrameCipherTest {
  private final byte[] key = Handshake.deriveKey("sys", "secret");
  private final UUID a = UUID.randomUUID();
  private final UUID b = UUID.randomUUID();
  private final byte[] nonceA = new byte[32];
  private final byte[] nonceB = new byte[32];
  private final FrameCipher atA;
  private final FrameCipher atB;

  FrameCipherTest() {
    Arrays.fill(nonceA, (byte) 1);
    Arrays.fill(nonceB, (byte) 2);
    atA = new FrameCipher(key, a, b, nonceA, nonceB);
    atB = new FrameCipher(key, b, a, nonceB, nonceA);
  }

  private static byte[] frame(String text) {
    byte[] body = text.getBytes();
    return ByteBuffer.allocate(4 + 2 + body.length).putInt(2 + body.length).put((byte) 1)
        .put((byte) 10).put(body).array();
  }

  private static byte[] body(byte[] sealedFrame) {
    return Arrays.copyOfRange(sealedFrame, 4, sealedFrame.length);
  }

  @Test
  void framesRoundTripInBothDirectionsInOrder() throws GeneralSecurityException {
    for (int i = 0; i < 3; i++) {
      byte[] f = frame("to b " + i);
      assertArrayEquals(Arrays.copyOfRange(f, 4, f.length), atB.open(body(atA.seal(f))));
      byte[] g = frame("to a " + i);
      assertArrayEquals(Arrays.copyOfRange(g, 4, g.length), atA.open(body(atB.seal(g))));
    }
  }

  @Test
  void alteredReplayedOrWrongDirectionFramesFail() throws GeneralSecurityException {
    byte[] first = atA.seal(frame("one"));
    byte[] altered = body(first).clone();
    altered[3] ^= 1;
    assertThrows(GeneralSecurityException.class, () -> atB.open(altered));

    FrameCipher freshB = new FrameCipher(key, b, a, nonceB, nonceA);
    freshB.open(body(first));
    assertThrows(GeneralSecurityException.class, () -> freshB.open(body(first)), "replay");

    FrameCipher otherB = new FrameCipher(key, b, a, nonceB, nonceA);
    assertThrows(GeneralSecurityException.class, () -> otherB.open(body(otherB.seal(frame("x")))),
        "own direction's frame");
  }
}
