package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.testing.Await;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class LinkOutputTest {
  /** Records each write's length and when, by the output's own clock, its writer last moved on. */
  private static class Recording extends OutputStream {
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
    output.write(false);

    assertEquals(List.of(LinkOutput.PIECE, LinkOutput.PIECE, LinkOutput.PIECE, 100), socket.lengths);
    for (int i = 1; i < socket.stamps.size(); i++) {
      // A heartbeat that finds the writer in piece i measures its wait from then, not from the
      // start of the frame: a slow peer that takes every piece is not taken for one that stopped.
      assertTrue(socket.stamps.get(i) - socket.stamps.get(i - 1) > 0, socket.stamps.toString());
    }
    assertEquals(0, output.writingSince(), "nobody writes any more");
  }

  @Test
  void nothingIsWrittenAfterGoodbyeAndWhatWasQueuedAfterItCanBeTakenBack() throws Exception {
    Recording socket = new Recording();
    LinkOutput output = new LinkOutput(socket, null, () -> { });
    socket.output = output;
    byte[] before = new byte[10];
    byte[] after = new byte[20];
    output.offer(before);
    output.offer(Link.GOODBYE);
    output.offer(after);
    assertFalse(output.write(false));
    assertEquals(List.of(10, Link.GOODBYE.length), socket.lengths);
    assertTrue(output.drained(), "a link that said goodbye has nothing more to write");
    assertFalse(output.write(false));
    assertEquals(2, socket.lengths.size(), "nor on a later write");
    assertFalse(output.withdraw(before), "written");
    assertTrue(output.withdraw(after));
    assertEquals(0, output.queuedBytes());
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
    output.write(false);

    assertEquals(frames, socket.lengths.size());
    long distinct = socket.stamps.stream().distinct().count();
    assertTrue(distinct >= 4 && distinct <= 5, distinct + " distinct times");
  }

  /** A socket whose peer takes nothing until {@link #release}. */
  private static final class Stalled extends OutputStream {
    final CountDownLatch writing = new CountDownLatch(1);
    final CountDownLatch released = new CountDownLatch(1);

    @Override
    public void write(int b) throws IOException {
      write(new byte[] {(byte) b}, 0, 1);
    }

    @Override
    public void write(byte[] b, int off, int len) throws IOException {
      writing.countDown();
      try {
        released.await();
      } catch (InterruptedException e) {
        throw new IOException(e);
      }
    }

    void release() {
      released.countDown();
    }
  }

  @Test
  void sendersWaitForRoomWhileThePeerTakesNothingAndGoOnOnceItDoes() throws Exception {
    Stalled socket = new Stalled();
    LinkOutput output = new LinkOutput(socket, null, () -> { }, 1000, frame -> false);
    output.offer(new byte[600]);
    CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
      try {
        output.write(false);
      } catch (IOException e) {
        throw new IllegalStateException(e);
      }
    });
    socket.writing.await();
    assertTrue(output.hasRoom(), "600 of 1000 bytes");
    output.offer(new byte[600]); // queued behind the stalled write: no room now
    assertEquals(1200, output.queuedBytes());
    assertTrue(!output.hasRoom());
    long soon = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(50);
    assertTrue(!output.awaitRoom(soon, () -> false), "the deadline passes first");

    CompletableFuture<Boolean> waiting = CompletableFuture.supplyAsync(() -> {
      try {
        return output.awaitRoom(System.nanoTime() + TimeUnit.SECONDS.toNanos(20), () -> false);
      } catch (InterruptedException e) {
        throw new IllegalStateException(e);
      }
    });
    socket.release();
    assertTrue(waiting.get(10, TimeUnit.SECONDS), "room once the peer takes the frames");
    writer.get(10, TimeUnit.SECONDS);
    assertEquals(0, output.queuedBytes());
  }

  @Test
  void aLinkThatClosesWakesTheSendersWaitingForRoom() throws Exception {
    Stalled socket = new Stalled();
    LinkOutput output = new LinkOutput(socket, null, () -> { }, 100, frame -> false);
    output.offer(new byte[600]);
    CompletableFuture.runAsync(() -> {
      try {
        output.write(false);
      } catch (IOException e) {
        // the test ends the write
      }
    });
    socket.writing.await();
    AtomicBoolean closed = new AtomicBoolean();
    CompletableFuture<Boolean> waiting = new CompletableFuture<>();
    Thread sender = new Thread(() -> {
      try {
        waiting.complete(output.awaitRoom(System.nanoTime() + TimeUnit.SECONDS.toNanos(20),
            closed::get));
      } catch (InterruptedException e) {
        waiting.completeExceptionally(e);
      }
    });
    sender.start();
    Await.until(java.time.Duration.ofSeconds(10),
        () -> sender.getState() == Thread.State.TIMED_WAITING, "the sender waiting for room");
    closed.set(true);
    output.wakeRoomWaiters(); // as Link.close does
    assertTrue(waiting.get(5, TimeUnit.SECONDS), "it goes on (to find the link closed) at once");
    socket.release();
  }

  @Test
  void aThreadWithWorkOfItsOwnStopsWritingForOthersAfterItsBudget() throws Exception {
    // A socket that takes 2 ms for each write, as a slow link does once its buffers are full.
    Recording socket = new Recording() {
      @Override
      public void write(byte[] b, int off, int len) {
        super.write(b, off, len);
        java.util.concurrent.locks.LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(2));
      }
    };
    LinkOutput output = new LinkOutput(socket, null, () -> { });
    socket.output = output;
    for (int i = 0; i < 10; i++) {
      output.offer(new byte[2 * Link.BUFFER]);
    }
    assertTrue(output.write(true), "frames left for another thread");
    int written = socket.lengths.size();
    assertTrue(written >= 2 && written < 10, written + " frames written");
    assertTrue(!output.drained());

    // A thread that writes for the link alone (a worker) writes everything.
    assertTrue(!output.write(false));
    assertEquals(10, socket.lengths.size());
    assertTrue(output.drained());
    assertEquals(0, output.queuedBytes());
  }

  @Test
  void aCongestedLinkLeavesOutTheFramesNobodyWaitsForAnyMore() throws Exception {
    Recording socket = new Recording();
    java.util.Set<byte[]> givenUp = java.util.Collections.newSetFromMap(
        new java.util.IdentityHashMap<>());
    LinkOutput output = new LinkOutput(socket, null, () -> { }, LinkOutput.ROOM, givenUp::contains);
    socket.output = output;
    int size = 64 * 1024;
    int frames = (int) (2 * LinkOutput.CONGESTED / size);
    for (int i = 0; i < frames; i++) {
      byte[] frame = new byte[size];
      if (i % 2 == 1) {
        givenUp.add(frame);
      }
      output.offer(frame);
    }
    output.write(false);
    // Left out while at least CONGESTED bytes waited (the first half of the frames); the rest go.
    int leftOut = frames - socket.lengths.size();
    assertTrue(leftOut >= frames / 4 - 1 && leftOut <= frames / 2, leftOut + " of " + frames);
    assertEquals(0, output.queuedBytes());
    assertTrue(output.drained());
  }

  /** A CALL frame with this timeout, as {@link RemoteCalls} makes one (no arguments). */
  private static byte[] call(int timeoutMs) {
    var out = Frames.start(Wire.CALL, 64);
    Frames.writeRouting(out, new java.util.UUID(1, 2), new java.util.UUID(3, 4), Wire.MAX_HOPS);
    out.writeLong(7); // request id
    out.writeLong(1); // service id
    out.writeInt(timeoutMs);
    out.writeVarUInt(0);
    return Frames.finish(out);
  }

  private static int timeoutOf(byte[] frame) {
    return java.nio.ByteBuffer.wrap(frame).getInt(Wire.HEADER + Frames.ROUTING + 16);
  }

  @Test
  void aCallPassedOnWhoseTimeRanOutWhileItWaitedIsLeftOutAndTheOthersCarryWhatTimeIsLeft()
      throws Exception {
    List<byte[]> written = new ArrayList<>();
    Recording socket = new Recording() {
      @Override
      public void write(byte[] b, int off, int len) {
        super.write(b, off, len);
        written.add(java.util.Arrays.copyOfRange(b, off, off + len));
      }
    };
    LinkOutput output = new LinkOutput(socket, null, () -> { });
    socket.output = output;
    output.offerPassedOn(call(1));
    output.offerPassedOn(call(60_000));
    output.offerPassedOn(call(1));
    long offered = System.nanoTime();
    Await.until(java.time.Duration.ofSeconds(5),
        () -> System.nanoTime() - offered > TimeUnit.MILLISECONDS.toNanos(5), "5 ms to pass");
    output.write(false);

    assertEquals(1, written.size(), "the two calls whose time was up were left out");
    int left = timeoutOf(written.get(0));
    assertTrue(left > 59_000 && left < 60_000, "the time left, not the time given: " + left);
    assertEquals(0, output.queuedBytes());
    assertTrue(output.drained());
  }
}
