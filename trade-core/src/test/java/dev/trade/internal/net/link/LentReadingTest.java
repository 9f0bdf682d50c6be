package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import dev.trade.internal.codec.ByteSink;
import dev.trade.testing.Await;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A caller waiting for its reply over a link reads the link itself (no thread hands it the reply);
 * the link's thread reads again once callers stop; a call read by a caller is served on another
 * thread, and a frame still arriving is left to the link's thread, so the caller never waits for
 * either; what is sent during a burst the caller hands out leaves while it waits on; a link that
 * ends while a caller reads ends once.
 */
@Timeout(60)
class LentReadingTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  /** The last payload byte of a PING that the handler answers. */
  private static final byte ASKS = 7;
  private final ExecutorService workers = Executors.newCachedThreadPool();
  private final List<Link> watched = new CopyOnWriteArrayList<>();
  private final ReadWatch watch = new ReadWatch(watched, workers, "lent");
  private final LoopbackLinks links = new LoopbackLinks();
  private final Socket[] far = new Socket[1];

  @AfterEach
  void close() throws IOException {
    links.close();
    watch.close();
    workers.shutdownNow();
  }

  /** Records on which thread each frame was handed out; completes the reply a caller waits for. */
  private static final class Handler implements LinkHandler {
    final CompletableFuture<byte[]> reply = new CompletableFuture<>();
    final BlockingQueue<Thread> replyReaders = new LinkedBlockingQueue<>();
    final BlockingQueue<Thread> callServers = new LinkedBlockingQueue<>();
    final CountDownLatch callMayEnd = new CountDownLatch(1);
    final AtomicInteger closings = new AtomicInteger();
    volatile String why;
    /** Sent back for each PING that {@link #ASKS}, if set. */
    volatile byte[] answerPings;

    @Override
    public boolean frame(Link link, int type, byte[] payload) {
      if (type == Wire.CALL) {
        return link.serveHere(() -> {
          callServers.add(Thread.currentThread());
          try {
            callMayEnd.await(); // a slow service
          } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
          }
        });
      }
      if (type != Wire.REPLY) {
        byte[] answer = answerPings;
        if (type == Wire.PING && answer != null && payload[7] == ASKS) {
          try {
            link.send(answer); // as a reply to a call would be sent
          } catch (IOException e) {
            throw new UncheckedIOException(e);
          }
        }
        return true;
      }
      replyReaders.add(Thread.currentThread());
      reply.complete(payload);
      return true;
    }

    @Override
    public void closed(Link link, String why) {
      this.why = why;
      closings.incrementAndGet();
    }
  }

  private Link started(Handler h) throws IOException {
    return started(h, new ReadRole());
  }

  private Link started(Handler h, ReadRole role) throws IOException {
    Link link = links.link(UUID.randomUUID(), "lentpeer", far, role);
    watched.add(link);
    link.start(h, watch);
    return link;
  }

  /**
   * Who reads a link where lending pays for a lone caller that called up to a minute ago: a test
   * whose caller called "just before" stays one on a machine that pauses it for milliseconds
   * between two lines. The linger still follows its period (ReadRoleTest), so it ends soon after
   * the test's last call.
   */
  private static ReadRole lendingForAMinute() {
    return new ReadRole(ReadRole.MIN_LINGER_NANOS, TimeUnit.MINUTES.toNanos(1), System::nanoTime);
  }

  private void sendFromFar(int type) throws IOException {
    far[0].getOutputStream().write(frameOf(type));
    far[0].getOutputStream().flush();
  }

  private static byte[] frameOf(int type) {
    return frameOf(type, 42);
  }

  private static byte[] frameOf(int type, long payload) {
    ByteSink out = Frames.start(type, 8);
    out.writeLong(payload);
    return Frames.finish(out);
  }

  /**
   * A caller counts itself on the link; a frame from the far end then lets the link's thread,
   * blocked in a read before, see the caller and lend it reading.
   */
  private void borrow(Link link) throws IOException {
    link.role.borrow();
    sendFromFar(Wire.PING);
    Await.until(WAIT, link.role::isLent, "the link's thread to lend reading");
  }

  private static long in(Duration d) {
    return System.nanoTime() + d.toNanos();
  }

  @Test
  void aCallerWaitingForItsReplyReadsItItself() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    sendFromFar(Wire.REPLY);
    link.reader.readFor(h.reply, in(WAIT));
    link.role.giveBack(false);
    assertTrue(h.reply.isDone(), "the reply came within the wait");
    assertSame(Thread.currentThread(), h.replyReaders.poll(), "the caller read its reply");
  }

  /**
   * A lone caller that spun in vain waits for its reply in a read of its own: the reply wakes it,
   * not the link's thread, which would then have to wake it.
   */
  @Test
  void aLoneCallerWhoseReplyComesAfterItsSpinWaitsInAReadAndReadsItItself() throws Exception {
    assumeTrue(Runtime.getRuntime().availableProcessors() > 1, "callers wait actively on 2+ cores");
    Handler h = new Handler();
    Link link = started(h, lendingForAMinute());
    ReplyWait wait = new ReplyWait(WAIT.toNanos());
    link.role.touch(); // a lone caller called just before
    assertTrue(wait.borrow(link), "a lone caller reads its reply itself");
    sendFromFar(Wire.PING); // lets the link's thread, blocked in a read, see the caller
    Await.until(WAIT, link.role::isLent, "the link's thread to lend reading");
    Thread[] caller = new Thread[1];
    long spunLongAgo = System.nanoTime() - Duration.ofSeconds(1).toNanos();
    Future<byte[]> reply = workers.submit(() -> {
      caller[0] = Thread.currentThread();
      return wait.await(link, true, h.reply, spunLongAgo);
    });
    Await.until(WAIT, link.role::isCallerReading, "the caller to wait in a read");
    sendFromFar(Wire.REPLY);
    assertEquals(8, reply.get(WAIT.toMillis(), TimeUnit.MILLISECONDS).length, "the reply");
    assertSame(caller[0], h.replyReaders.poll(), "the caller read its reply");
    Await.until(WAIT, () -> !link.role.isLent(), "the link's thread to take reading back");
  }

  /**
   * A control loop's caller: a call about every millisecond, each reply slower than a spin's
   * worth. It reads its replies itself: reading stays lent from one call to the next, and a
   * reply the link's thread hands over (the second: reading was not lent yet) leaves it lent for
   * the next. The linger is a minute here, so that a busy machine that stretches a pause beyond
   * the product's 2 ms changes nothing; how long it lingers is ReadRoleTest's.
   */
  @Test
  void aControlLoopsCallerReadsItsOwnRepliesThoughTheyComeSlowly() throws Exception {
    int calls = 30;
    AtomicReference<CompletableFuture<byte[]>> current = new AtomicReference<>();
    BlockingQueue<Thread> readers = new LinkedBlockingQueue<>();
    long minute = TimeUnit.MINUTES.toNanos(1);
    Link link = links.link(UUID.randomUUID(), "lentpeer", far,
        new ReadRole(minute, minute, System::nanoTime));
    watched.add(link);
    link.start(new LinkHandler() {
      @Override
      public boolean frame(Link l, int type, byte[] payload) {
        if (type == Wire.REPLY) {
          readers.add(Thread.currentThread());
          current.get().complete(payload);
        }
        return true;
      }

      @Override
      public void closed(Link l, String why) {}
    }, watch);
    ReplyWait wait = new ReplyWait(WAIT.toNanos());
    BlockingQueue<Integer> sent = new LinkedBlockingQueue<>();
    Future<?> provider = workers.submit(() -> { // replies once the caller waits, a while later
      for (int i = 0; i < calls; i++) {
        int call = sent.take();
        long until = System.nanoTime() + WAIT.toNanos();
        while (wait.waiting() == 0 && System.nanoTime() - until < 0) {
          Thread.onSpinWait(); // until the caller waits: a reply slower than a spin's worth follows
        }
        assertEquals(1, wait.waiting(), "the caller waits for reply " + call);
        long served = System.nanoTime() + TimeUnit.MICROSECONDS.toNanos(150); // the service's time
        while (System.nanoTime() - served < 0) {
          Thread.onSpinWait();
        }
        sendFromFar(Wire.REPLY);
      }
      return null;
    });
    int readHere = 0;
    for (int i = 0; i < calls; i++) {
      LockSupport.parkNanos(TimeUnit.MICROSECONDS.toNanos(500)); // the loop's pause, not a wait
      CompletableFuture<byte[]> reply = new CompletableFuture<>();
      current.set(reply);
      boolean borrowed = wait.borrow(link);
      sent.add(i);
      assertEquals(8, wait.await(link, borrowed, reply, System.nanoTime()).length);
      if (readers.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS) == Thread.currentThread()) {
        readHere++;
      }
    }
    provider.get(WAIT.toMillis(), TimeUnit.MILLISECONDS);
    // The first call does not borrow (no lone call came before it), and the second's reply
    // reaches the link's thread blocked in a read; from then on reading stays lent. Before, it
    // read none after the first pause.
    assertEquals(calls - 2, readHere, "the caller read " + readHere + " of its " + calls + " replies");
    assertEquals(0, link.role.parked(), "a caller still counted as parked");
  }

  /**
   * A call served on the link's thread that calls back the peer whose call it serves (a hook whose
   * wrapper is in the caller's container; any re-entrant call): it reads the call back's reply
   * itself, and then reading goes back to the link's thread at once. The peer's next frame (its
   * next call) comes only after the served call's reply: left lent for the linger, reading would
   * lend to nobody, and that frame would wait for the linger to end (HookBench measured about a
   * millisecond a call). The clock stands still here, so the linger never ends by itself: only the
   * call back's end can give reading back.
   */
  @Test
  void aServedCallThatCallsThePeerBackLeavesReadingToTheLinksThreadAtOnce() throws Exception {
    ReadRole stillClock = new ReadRole(ReadRole.MIN_LINGER_NANOS, ReadRole.LINGER_NANOS, () -> 0L);
    Link link = links.link(UUID.randomUUID(), "lentpeer", far, stillClock);
    watched.add(link);
    ReplyWait wait = new ReplyWait(WAIT.toNanos());
    CompletableFuture<byte[]> callBack = new CompletableFuture<>();
    CompletableFuture<Boolean> served = new CompletableFuture<>();
    BlockingQueue<Integer> handedOut = new LinkedBlockingQueue<>();
    link.start(new LinkHandler() {
      @Override
      public boolean frame(Link l, int type, byte[] payload) {
        handedOut.add(type);
        if (type == Wire.REPLY) {
          callBack.complete(payload);
        }
        return type != Wire.CALL || l.serveHere(() -> {
          try { // as RemoteCalls.call calls out
            ServedCalls.releaseReading();
            l.role.touch(); // a lone caller called just before: it reads its reply itself
            boolean borrowed = wait.borrow(l);
            l.send(frameOf(Wire.CALL, 99));
            wait.await(l, borrowed, callBack, System.nanoTime());
            served.complete(borrowed);
          } catch (Exception e) {
            served.completeExceptionally(e);
          }
        });
      }

      @Override
      public void closed(Link l, String why) {}
    }, watch);
    sendFromFar(Wire.CALL);
    byte[] calledBack = far[0].getInputStream().readNBytes(frameOf(Wire.CALL, 99).length);
    assertEquals(Wire.CALL, calledBack[5], "the call back reached the peer");
    sendFromFar(Wire.REPLY);
    assertTrue(served.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the call back borrowed");
    assertEquals(List.of(Wire.CALL, Wire.REPLY), List.of(handedOut.take(), handedOut.take()));
    sendFromFar(Wire.PING); // the peer's next frame, once it has its reply
    assertEquals(Wire.PING, handedOut.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS),
        "the peer's next frame waits for a linger that never ends");
    assertFalse(link.role.isLent());
  }

  /**
   * A lone caller whose reply comes later than its read wait parks, still counted as reading its
   * replies: the link's thread must take reading back at once and read the reply for it, not
   * wait for it to stop borrowing.
   */
  @Test
  void aReplyLaterThanTheCallersReadWaitIsReadForItByTheLinksThread() throws Exception {
    Handler h = new Handler();
    Link link = started(h, lendingForAMinute());
    ReplyWait wait = new ReplyWait(TimeUnit.MILLISECONDS.toNanos(5));
    link.role.touch(); // a lone caller called just before
    assertTrue(wait.borrow(link), "a lone caller calling again at once reads its reply itself");
    sendFromFar(Wire.PING); // lets the link's thread, blocked in a read, see the caller
    Await.until(WAIT, link.role::isLent, "the link's thread to lend reading");
    Thread[] caller = new Thread[1];
    Future<byte[]> reply = workers.submit(() -> {
      caller[0] = Thread.currentThread();
      return wait.await(link, true, h.reply, System.nanoTime());
    });
    Await.until(WAIT, () -> !link.role.isLent(), "the link's thread to read for the caller");
    sendFromFar(Wire.REPLY);
    assertEquals(8, reply.get(WAIT.toMillis(), TimeUnit.MILLISECONDS).length, "the reply");
    assertNotEquals(caller[0], h.replyReaders.poll(), "the parked caller read its reply");
    assertEquals(0, link.role.parked());
  }

  /** A caller waiting in a read gives reading back in time, and the link's thread reads on. */
  @Test
  void aCallerWaitingInAReadStopsInTimeAndLeavesNoReadTimeoutBehind() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    CompletableFuture<byte[]> none = new CompletableFuture<>(); // no reply comes
    long start = System.nanoTime();
    link.reader.blockFor(none, start + Duration.ofMillis(20).toNanos());
    assertTrue(System.nanoTime() - start < WAIT.toNanos(), "stopped waiting");
    assertEquals(0, link.readTimeout(), "the link's thread reads without a timeout");
    link.role.giveBack(false);
    Await.until(WAIT, () -> !link.role.isLent(), "the link's thread to take reading back");
    sendFromFar(Wire.REPLY);
    Thread reader = h.replyReaders.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS);
    assertNotEquals(null, reader, "a frame after the caller stopped was read");
    assertNotEquals(Thread.currentThread(), reader);
    assertEquals(0, h.closings.get(), "the link is open: " + h.why);
  }

  @Test
  void theLinksThreadReadsAgainOnceCallersStop() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    link.reader.readFor(new CompletableFuture<>(), in(Duration.ofMillis(1))); // no reply comes
    link.role.giveBack(false);
    Await.until(WAIT, () -> !link.role.isLent(), "the link's thread to take reading back");
    sendFromFar(Wire.REPLY);
    Thread reader = h.replyReaders.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS);
    assertNotEquals(null, reader, "a frame after the callers stopped was read");
    assertNotEquals(Thread.currentThread(), reader);
  }

  @Test
  void aCallThatACallerReadsIsServedOnAnotherThreadAndTheCallerGetsItsReply() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    sendFromFar(Wire.CALL); // a slow call read by the caller, then the caller's reply
    sendFromFar(Wire.REPLY);
    Thread caller = Thread.currentThread();
    try {
      link.reader.readFor(h.reply, in(WAIT));
      link.role.giveBack(!h.reply.isDone());
      assertEquals(8, h.reply.get(WAIT.toMillis(), TimeUnit.MILLISECONDS).length, "the reply");
      Thread server = h.callServers.poll(WAIT.toMillis(), TimeUnit.MILLISECONDS);
      assertNotEquals(null, server, "the call was served");
      assertNotEquals(caller, server, "the caller served a call it read");
    } finally {
      h.callMayEnd.countDown();
    }
  }

  @Test
  void whatIsSentWhileACallerHandsOutABurstLeavesWhileItWaitsOn() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    h.answerPings = frameOf(Wire.PING);
    Future<?> caller = workers.submit(() -> {
      link.reader.readFor(h.reply, in(WAIT));
      link.role.giveBack(!h.reply.isDone());
    });
    Await.until(WAIT, link.role::isCallerReading, "the caller to read");
    byte[] ping = frameOf(Wire.PING, ASKS);
    byte[] other = frameOf(Wire.LINKS, 0); // not answered
    byte[] two = new byte[ping.length + other.length]; // two frames in one write: a burst
    System.arraycopy(ping, 0, two, 0, ping.length);
    System.arraycopy(other, 0, two, ping.length, other.length);
    far[0].getOutputStream().write(two);
    far[0].getOutputStream().flush();
    // The answer to the ping waits for the end of the burst; the caller, still waiting for its
    // reply, must write it then (the far end's read fails after 5 s).
    byte[] got = far[0].getInputStream().readNBytes(h.answerPings.length);
    assertEquals(h.answerPings.length, got.length, "the answer arrived");
    assertFalse(caller.isDone(), "the caller still waits for its reply");
    sendFromFar(Wire.REPLY);
    caller.get(WAIT.toMillis(), TimeUnit.MILLISECONDS);
  }

  @Test
  void aLinkThatACallerFindsBrokenEndsOnce() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    Future<?> caller = workers.submit(() -> {
      link.reader.readFor(h.reply, in(Duration.ofMinutes(2))); // its reply never comes
      link.role.giveBack(!h.reply.isDone());
    });
    Await.until(WAIT, link.role::isCallerReading, "the caller to read");
    far[0].getOutputStream().write(new byte[] {0, 0, 0, 1, 0}); // a frame shorter than allowed
    far[0].getOutputStream().flush();
    caller.get(WAIT.toMillis(), TimeUnit.MILLISECONDS); // it stops once the link has ended
    assertEndedOnce(link, h, "malformed frame from lentpeer: length 1 (limit MAXFRAMESIZE=1048576)");
  }

  @Test
  void aCallerNeverWaitsForAFrameThatHasNotArrivedWhole() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    ByteSink out = Frames.start(Wire.REPLY, 8);
    out.writeLong(42);
    byte[] reply = Frames.finish(out);
    int half = reply.length / 2;
    far[0].getOutputStream().write(reply, 0, half); // the peer stalls within the frame
    far[0].getOutputStream().flush();
    Future<?> caller = workers.submit(() -> {
      link.reader.readFor(h.reply, in(Duration.ofMillis(50)));
      link.role.giveBack(!h.reply.isDone());
    });
    caller.get(WAIT.toMillis(), TimeUnit.MILLISECONDS); // its time ran out: it did not block
    assertFalse(h.reply.isDone(), "half a reply was handed out");
    far[0].getOutputStream().write(reply, half, reply.length - half);
    far[0].getOutputStream().flush();
    assertEquals(8, h.reply.get(WAIT.toMillis(), TimeUnit.MILLISECONDS).length,
        "the link's thread read the rest");
  }

  @Test
  void aPeerThatLeavesWhileACallerWaitsIsNoticedOnceTheCallerStops() throws Exception {
    Handler h = new Handler();
    Link link = started(h);
    borrow(link);
    far[0].close();
    // The caller cannot tell an end from silence without blocking; its wait is short, and the
    // link's thread, reading again, finds the end.
    link.reader.readFor(h.reply, in(Duration.ofMillis(1)));
    link.role.giveBack(!h.reply.isDone());
    Await.until(WAIT, link::isClosed, "the link to close");
    assertEndedOnce(link, h, "connection closed by lentpeer");
  }

  private static void assertEndedOnce(Link link, Handler h, String why) {
    assertTrue(link.isClosed());
    Await.until(WAIT, () -> h.closings.get() > 0 && Thread.getAllStackTraces().keySet().stream()
        .noneMatch(t -> t.getName().equals("trade-link-lentpeer")), "the link's threads to end");
    assertEquals(1, h.closings.get(), "times the handler heard of the end");
    assertEquals(why, h.why);
  }
}
