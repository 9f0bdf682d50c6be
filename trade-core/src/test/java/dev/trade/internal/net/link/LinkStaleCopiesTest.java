package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.ByteSink;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A link asks its handler once per frame whether the frame is stale, before handing it out: in
 * its input buffer when the frame is there whole (a stale copy is then dropped without being
 * copied out), else once the frame is read. Stale frames never reach the handler, and the frames
 * after them arrive intact.
 */
class LinkStaleCopiesTest {
  private static final byte STALE = 1;
  private static final byte FRESH = 2;
  private final LoopbackLinks links = new LoopbackLinks();
  private final Socket[] far = new Socket[1];
  private final ExecutorService workers = Executors.newCachedThreadPool();
  private final ReadWatch watch = new ReadWatch(List.of(), workers, "test");

  @AfterEach
  void close() throws IOException {
    links.close();
    watch.close();
    workers.shutdownNow();
  }

  /** Judges a payload stale by its first byte; records what it was asked and what it was given. */
  private static final class Judge implements LinkHandler {
    /** Per question: the payload's length, and whether it lay amid other bytes (the buffer). */
    final List<int[]> asked = new CopyOnWriteArrayList<>();
    final BlockingQueue<byte[]> delivered = new LinkedBlockingQueue<>();

    @Override
    public boolean isStale(Link link, int type, byte[] buf, int off, int len) {
      asked.add(new int[] {len, off != 0 || len != buf.length ? 1 : 0});
      return buf[off] == STALE;
    }

    @Override
    public boolean frame(Link link, int type, byte[] payload) {
      delivered.add(payload);
      return true;
    }

    @Override
    public void closed(Link link, String why) {}
  }

  private static byte[] frame(byte kind, int size) {
    ByteSink out = Frames.start(Wire.LINKS, size);
    byte[] payload = new byte[size];
    payload[0] = kind;
    payload[size - 1] = (byte) size; // the end arrives too
    out.writeBytes(payload, 0, size);
    return Frames.finish(out);
  }

  private Judge start() throws IOException {
    Judge judge = new Judge();
    links.link(UUID.randomUUID(), "C", far).start(judge, watch);
    return judge;
  }

  private void send(byte[]... frames) throws IOException {
    ByteArrayOutputStream all = new ByteArrayOutputStream();
    for (byte[] f : frames) {
      all.write(f);
    }
    far[0].getOutputStream().write(all.toByteArray()); // one write: the reader finds them buffered
    far[0].getOutputStream().flush();
  }

  private static void assertFresh(byte[] payload, int size) {
    assertEquals(size, payload.length);
    assertEquals(FRESH, payload[0]);
    assertEquals((byte) size, payload[size - 1]);
  }

  @Test
  void staleCopiesInTheBufferAreDroppedThereAndTheRestArrivesIntact() throws Exception {
    Judge judge = start();
    send(frame(STALE, 700), frame(FRESH, 300), frame(STALE, 90), frame(STALE, 700), frame(FRESH, 41));
    assertFresh(judge.delivered.poll(5, TimeUnit.SECONDS), 300);
    assertFresh(judge.delivered.poll(5, TimeUnit.SECONDS), 41);
    assertEquals(5, judge.asked.size(), "asked once per frame");
    for (int[] q : judge.asked) {
      assertEquals(1, q[1], "a frame of " + q[0] + " bytes was copied out of the buffer to be judged");
    }
    assertTrue(judge.delivered.isEmpty());
  }

  @Test
  void aFrameLargerThanTheBufferIsJudgedOnceRead() throws Exception {
    Judge judge = start();
    send(frame(STALE, 20_000), frame(FRESH, 30_000), frame(FRESH, 12));
    assertFresh(judge.delivered.poll(5, TimeUnit.SECONDS), 30_000);
    assertFresh(judge.delivered.poll(5, TimeUnit.SECONDS), 12);
    assertEquals(3, judge.asked.size(), "asked once per frame");
    assertEquals(20_000, judge.asked.get(0)[0]);
    assertEquals(0, judge.asked.get(0)[1], "judged in its own array, read whole first");
    assertEquals(0, judge.asked.get(1)[1]);
  }
}
