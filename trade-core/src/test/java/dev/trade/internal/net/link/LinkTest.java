package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.ByteSink;
import dev.trade.testing.Await;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A link reports why it was closed (the first reason given to close(), not a generic "closed"; a
 * goodbye read after a write to the departed peer failed); it
 * goes on being read while its reading thread serves a long call; a served call that waits for a
 * remote reply lets reading go on at once; replies sent during a burst of calls all leave.
 */
class LinkTest {
  private ServerSocket server;
  private Socket near;
  private Socket far;
  private final ExecutorService workers = Executors.newCachedThreadPool();
  private final ReadWatch watch = new ReadWatch(List.of(), workers, "test");

  @BeforeEach
  void connect() throws IOException {
    server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    near = new Socket();
    near.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), server.getLocalPort()));
    far = server.accept();
  }

  @AfterEach
  void close() throws IOException {
    near.close();
    far.close();
    server.close();
    watch.close();
    workers.shutdownNow();
  }

  private static Handshake.Peer peer(String name) {
    return new Handshake.Peer(UUID.randomUUID(), name, "host", List.of(), null); // no encryption
  }

  /** Records the reason the link reports when it closes; closes it on GOODBYE, as Network does. */
  private static final class Recorder implements LinkHandler {
    final CompletableFuture<String> reason = new CompletableFuture<>();

    @Override
    public boolean frame(Link link, int type, byte[] payload) {
      if (type == Wire.GOODBYE) {
        link.close("said goodbye");
      }
      return true;
    }

    @Override
    public void closed(Link link, String why) {
      reason.complete(why);
    }
  }

  @Test
  void aLinkClosedHereReportsTheReasonGiven() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r, watch);
    link.close("silent for 3012 ms (FAILURETIMEOUT=3000)");
    assertEquals("silent for 3012 ms (FAILURETIMEOUT=3000)", r.reason.get(5, TimeUnit.SECONDS));
    assertTrue(link.isClosed());
  }

  @Test
  void aLinkClosedByItsHandlerReportsThatReason() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r, watch);
    far.getOutputStream().write(Frames.finish(Frames.start(Wire.GOODBYE, 0)));
    far.getOutputStream().flush();
    assertEquals("said goodbye", r.reason.get(5, TimeUnit.SECONDS));
  }

  @Test
  void aLinkClosedByThePeerSaysSo() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r, watch);
    far.close();
    assertEquals("connection closed by C", r.reason.get(5, TimeUnit.SECONDS));
  }

  @Test
  void aPeerThatSaidGoodbyeBeforeOurWriteFailedLeftInOrder() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    byte[] ping = Frames.finish(Frames.start(Wire.PING, 0));
    link.send(ping); // left unread by the peer: its close then resets the connection
    sendFromFar(Frames.finish(Frames.start(Wire.GOODBYE, 0)));
    far.close();
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
    boolean failed = false;
    while (!failed && System.nanoTime() < deadline) { // until the reset has come back
      try {
        link.send(ping);
      } catch (IOException e) {
        failed = true;
      }
    }
    assertTrue(failed, "a write to a closed peer failed");
    assertTrue(link.isClosed(), "senders see the link closed");
    assertThrows(IOException.class, () -> link.send(ping));
    Recorder r = new Recorder();
    link.start(r, watch);
    assertEquals("said goodbye", r.reason.get(5, TimeUnit.SECONDS), "the goodbye was read");
  }

  @Test
  void queuedFramesLeaveTogetherWhenFlushed() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    byte[] ping = Frames.finish(Frames.start(Wire.PING, 0));
    link.queue(ping);
    link.queue(ping);
    far.setSoTimeout(200);
    assertThrows(SocketTimeoutException.class, () -> far.getInputStream().read(),
        "a queued frame was written before the flush");
    link.flushQueued();
    byte[] both = far.getInputStream().readNBytes(2 * ping.length);
    assertArrayEquals(ping, Arrays.copyOfRange(both, 0, ping.length));
    assertArrayEquals(ping, Arrays.copyOfRange(both, ping.length, both.length));
    link.close("done");
    assertThrows(IOException.class, () -> link.queue(ping), "queued on a closed link");
  }

  @Test
  void onlyTheFirstReasonCounts() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.close("duplicate link");
    link.close("container closing");
    link.start(r, watch);
    assertEquals("duplicate link", r.reason.get(5, TimeUnit.SECONDS));
  }

  /** A handler that serves every frame on the reading thread with {@code work} and records frames. */
  private static final class Serving implements LinkHandler {
    final BlockingQueue<Integer> seen = new LinkedBlockingQueue<>();
    final Consumer<Link> work;

    Serving(Consumer<Link> work) {
      this.work = work;
    }

    @Override
    public boolean frame(Link link, int type, byte[] payload) {
      seen.add(payload.length);
      return link.serveHere(() -> work.accept(link));
    }

    @Override
    public void closed(Link link, String why) {}
  }

  /** A frame whose payload length tells frames apart. */
  private static byte[] frame(int n) {
    ByteSink out = Frames.start(Wire.PING, n);
    out.writeBytes(new byte[n], 0, n);
    return Frames.finish(out);
  }

  private void sendFromFar(byte[]... frames) throws IOException {
    for (byte[] f : frames) {
      far.getOutputStream().write(f);
    }
    far.getOutputStream().flush();
  }

  @Test
  void aLongCallOnTheReadingThreadDoesNotStopReading() throws Exception {
    CountDownLatch release = new CountDownLatch(1);
    List<Link> watched = new CopyOnWriteArrayList<>();
    try (ReadWatch watching = new ReadWatch(watched, workers, "watching")) {
      Link link = new Link(near, peer("C"), true, 1 << 20);
      watched.add(link);
      Serving h = new Serving(l -> {
        try {
          release.await();
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
        }
      });
      link.start(h, watching);
      sendFromFar(frame(1));
      assertEquals(1, h.seen.poll(5, TimeUnit.SECONDS));
      sendFromFar(frame(2)); // read while the first call still blocks its thread
      assertEquals(2, h.seen.poll(5, TimeUnit.SECONDS));
      assertEquals(1, release.getCount(), "the first call is still being served");
      release.countDown();
      sendFromFar(frame(3));
      assertEquals(3, h.seen.poll(5, TimeUnit.SECONDS));
      link.close("done");
    }
  }

  @Test
  void theWatchSleepsWhileNoCallIsServed() throws Exception {
    List<Link> watched = new CopyOnWriteArrayList<>();
    try (ReadWatch watching = new ReadWatch(watched, workers, "sleepy")) {
      awaitParked(watching, "before any call");
      assertFalse(watching.isStarted(), "a thread before any call");
      Link link = new Link(near, peer("C"), true, 1 << 20);
      watched.add(link);
      Serving h = new Serving(l -> { });
      link.start(h, watching);
      for (int i = 1; i <= 20; i++) {
        sendFromFar(frame(i));
        assertEquals(i, h.seen.poll(5, TimeUnit.SECONDS));
      }
      assertTrue(watching.isStarted(), "started by the first call");
      awaitParked(watching, "after the calls");
      link.close("done");
    }
  }

  private static void awaitParked(ReadWatch watch, String when) {
    Await.until(Duration.ofSeconds(5), watch::isParked, "the watch to sleep " + when);
  }

  @Test
  void aServedCallThatWaitsForAReplyLetsReadingGoOnAtOnce() throws Exception {
    // The watch here never looks at this link: only releaseReading() can hand reading on.
    CountDownLatch release = new CountDownLatch(1);
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Serving h = new Serving(l -> {
      ServedCalls.releaseReading();
      try {
        release.await();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    });
    link.start(h, watch);
    sendFromFar(frame(1));
    assertEquals(1, h.seen.poll(5, TimeUnit.SECONDS));
    sendFromFar(frame(2));
    assertEquals(2, h.seen.poll(5, TimeUnit.SECONDS));
    release.countDown();
    link.close("done");
  }

  @Test
  void repliesToABurstOfCallsAllLeave() throws Exception {
    int burst = 200;
    Link link = new Link(near, peer("C"), true, 1 << 20);
    LinkHandler h = new LinkHandler() {
      @Override
      public boolean frame(Link l, int type, byte[] payload) {
        if (payload.length != 5) {
          return true; // not a call: no reply
        }
        return l.serveHere(() -> {
          try {
            l.send(LinkTest.frame(7));
          } catch (IOException e) {
            throw new UncheckedIOException(e);
          }
        });
      }

      @Override
      public void closed(Link l, String why) {}
    };
    link.start(h, watch);
    byte[][] calls = new byte[burst + 1][];
    Arrays.fill(calls, frame(5));
    calls[burst] = frame(1); // the last reply is sent while this frame waits in the buffer
    sendFromFar(calls); // one write: the link reads most of them from its buffer
    DataInputStream replies = new DataInputStream(far.getInputStream());
    far.setSoTimeout(5_000);
    for (int i = 0; i < burst; i++) {
      int length = replies.readInt();
      replies.readFully(new byte[length]);
      assertEquals(2 + 7, length, "reply " + i);
    }
    link.close("done");
  }

  @Test
  void framesOtherThreadsSendDuringABurstLeaveWhenItEnds() throws Exception {
    int burst = 20;
    Link link = new Link(near, peer("C"), true, 1 << 20);
    List<Integer> bytesAtTheFarEnd = new CopyOnWriteArrayList<>();
    Serving h = new Serving(l -> {
      // A caller this frame wakes calls again at once, from its own thread; on loopback a frame
      // written is at the far end when the write returns.
      sendOn(l, frame(9));
      try {
        bytesAtTheFarEnd.add(far.getInputStream().available());
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
    });
    link.start(h, watch);
    byte[][] frames = new byte[burst][];
    Arrays.fill(frames, frame(1));
    sendFromFar(concat(frames)); // one write: read as one burst
    DataInputStream sent = new DataInputStream(far.getInputStream());
    far.setSoTimeout(5_000);
    for (int i = 0; i < burst; i++) {
      assertEquals(2 + 9, sent.readInt(), "frame " + i);
      sent.readFully(new byte[2 + 9]);
    }
    Await.until(Duration.ofSeconds(5), () -> bytesAtTheFarEnd.size() == burst, "every frame handled");
    assertEquals(0, bytesAtTheFarEnd.get(0), "written before the burst ended");
    assertEquals(0, bytesAtTheFarEnd.get(burst - 2), "written before the burst ended");
    link.close("done");
  }

  @Test
  void aFlushThatBlocksAtTheEndOfABurstDoesNotStopReading() throws Exception {
    List<Link> watched = new CopyOnWriteArrayList<>();
    try (ReadWatch watching = new ReadWatch(watched, workers, "flushing")) {
      Link link = new Link(near, peer("C"), true, 1 << 20);
      watched.add(link);
      // Far more than the socket buffers hold while the far end reads nothing (as when its reader
      // is busy writing to us): the write at the end of the burst blocks.
      near.setSendBufferSize(64 << 10);
      far.setReceiveBufferSize(64 << 10);
      byte[] big = frame(16 << 20);
      AtomicBoolean once = new AtomicBoolean();
      Serving h = new Serving(l -> {
        if (once.compareAndSet(false, true)) {
          try {
            l.send(big); // a reply during a burst: queued, the burst's end writes it
          } catch (IOException e) {
            throw new UncheckedIOException(e);
          }
        }
      });
      link.start(h, watching);
      sendFromFar(concat(frame(1), frame(2)));
      assertEquals(1, h.seen.poll(5, TimeUnit.SECONDS));
      assertEquals(2, h.seen.poll(5, TimeUnit.SECONDS));
      sendFromFar(frame(3));
      assertEquals(3, h.seen.poll(5, TimeUnit.SECONDS), "read while the write blocks");
      link.close("done");
    }
  }

  /** Sends {@code frame} on {@code link} from another thread, and waits until send returns. */
  private void sendOn(Link link, byte[] frame) {
    try {
      CompletableFuture.runAsync(() -> {
        try {
          link.send(frame);
        } catch (IOException e) {
          throw new UncheckedIOException(e);
        }
      }, workers).get(5, TimeUnit.SECONDS);
    } catch (Exception e) {
      throw new IllegalStateException("send did not return", e);
    }
  }

  private static byte[] concat(byte[]... frames) {
    ByteSink all = new ByteSink(64);
    for (byte[] f : frames) {
      all.writeBytes(f, 0, f.length);
    }
    return all.toByteArray();
  }
}
