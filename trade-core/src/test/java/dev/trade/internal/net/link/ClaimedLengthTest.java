package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.testing.Allocations;
import java.io.ByteArrayInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A frame's payload is allocated as its bytes arrive, not for the length its header claims: a peer
 * that claims 64 MiB and sends 16 bytes makes the reader allocate about what it sent (before, the
 * whole claim, at once: six links claiming 12 MiB each ran a 64 MiB container out of memory).
 */
class ClaimedLengthTest {
  private static final int MAX_FRAME = 64 << 20;

  private static LinkInput input(byte[] bytes) {
    InputStream in = new ByteArrayInputStream(bytes);
    return new LinkInput(new Socket(), in, 64 << 10, "peer", MAX_FRAME, null,
        (type, buf, off, len) -> false, () -> {});
  }

  private static byte[] frame(int claimed, byte[] payload) {
    return ByteBuffer.allocate(4 + 2 + payload.length).putInt(claimed)
        .put((byte) Wire.VERSION).put((byte) Wire.CALL).put(payload).array();
  }

  @Test
  void aClaimOf64MiBWith16BytesBehindAllocatesAboutWhatArrived() {
    LinkInput in = input(frame(MAX_FRAME, new byte[16]));
    long before = Allocations.ofThisThread();
    assertThrows(EOFException.class, in::readFrame);
    long allocated = Allocations.ofThisThread() - before;
    assertTrue(allocated < 4 * LinkInput.FIRST_PAYLOAD, "allocated " + allocated + " bytes");
  }

  @Test
  void framesLargerThanTheFirstArrayArriveWhole() throws IOException {
    byte[] payload = new byte[3 * LinkInput.FIRST_PAYLOAD + 17];
    new Random(4).nextBytes(payload);
    LinkInput.Frame f = input(frame(payload.length + 2, payload)).readFrame();
    assertEquals(Wire.CALL, f.type());
    assertArrayEquals(payload, f.payload());
  }
}
