package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class LinkOutputTest {
  /** Records each write's length and when, by the output's own clock, its writer last moved on. */
  private static final class Recording extends OutputStream {
    final List<Integer> lengths = new ArrayList<>();
    final List<Long> stamps = new ArrayList<>();
    LinkOutput output;

    @Override
    public void write(int b) {
      write(new byte[] {(byte) b}, 0, 1);
    }

    @Override
    public void write(byte[] b, int off, int len) {
      lengths.add(len);
      stamps.add(output.writingSince());
    }
  }

  @Test
  void aLargeFrameGoesOutInPiecesAndEachPieceCountsAsProgress() throws Exception {
    Recording socket = new Recording();
    LinkOutput output = new LinkOutput(socket, null, () -> { });
    socket.output = output;
    output.offer(new byte[3 * LinkOutput.PIECE + 100]);
    output.write();

    assertEquals(List.of(LinkOutput.PIECE, LinkOutput.PIECE, LinkOutput.PIECE, 100), socket.lengths);
    for (int i = 1; i < socket.stamps.size(); i++) {
      // A heartbeat that finds the writer in piece i measures its wait from then, not from the
      // start of the frame: a slow peer that takes every piece is not taken for one that stopped.
      assertTrue(socket.stamps.get(i) - socket.stamps.get(i - 1) > 0, socket.stamps.toString());
    }
    assertEquals(0, output.writingSince(), "nobody writes any more");
  }

  @Test
  void smallFramesAreTimedOncePerBufferNotOncePerFrame() throws Exception {
    Recording socket = new Recording();
    LinkOutput output = new LinkOutput(socket, null, () -> { });
    socket.output = output;
    int frames = 4 * Link.BUFFER / 100;
    for (int i = 0; i < frames; i++) {
      output.offer(new byte[100]);
    }
    output.write();

    assertEquals(frames, socket.lengths.size());
    long distinct = socket.stamps.stream().distinct().count();
    assertTrue(distinct >= 4 && distinct <= 5, distinct + " distinct times");
  }
}
