package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.KEY;
import static dev.trade.internal.discovery.Fixtures.SYSTEM;
import static dev.trade.internal.discovery.Fixtures.announcement;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.StandardProtocolFamily;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The shared group socket keeps delivering whatever its receivers or its socket do (loopback,
 * TTL 0).
 */
class GroupSocketTest {
  @BeforeEach
  void multicast() {
    LoopbackMulticast.assumeUsable();
  }

  /** Throws on every dropped datagram: a receiver with a bug. */
  private static final class Failing implements Receiver.Observer {
    final AtomicInteger thrown = new AtomicInteger();

    @Override
    public void dropped(Reason reason) {
      thrown.incrementAndGet();
      throw new IllegalStateException("receiver bug");
    }
  }

  private static Receiver receiver(String id, List<DatagramChannel> answers,
      Discovery.Listener listener, Receiver.Observer observer) {
    return receiver(id, answers, listener, observer, Runnable::run);
  }

  private static Receiver receiver(String id, List<DatagramChannel> answers,
      Discovery.Listener listener, Receiver.Observer observer, Executor handler) {
    return new Receiver(answers, SYSTEM, id, KEY, listener, (a, from) -> { }, observer,
        new ReplayGuard(ReplayGuard.DEFAULT_MAX_SENDERS, Duration.ofSeconds(30)),
        Duration.ofSeconds(60), true, handler);
  }

  /**
   * The socket's one thread only reads; each container of the JVM handles what it hears on its
   * own executor. When that thread also ran every container's listener, one container's slow
   * handling (a dial starting a thread, a busy timer) held up every other container's discovery:
   * with 25 containers in a JVM of 100 starting, announcements were handled 14-22 s late.
   */
  @Test
  void aContainerStuckOnADatagramHoldsUpNoOtherContainer() throws Exception {
    InetSocketAddress target = new InetSocketAddress(LoopbackMulticast.randomGroup(),
        LoopbackMulticast.freePort());
    List<NetworkInterface> lo = List.of(LoopbackMulticast.loopback());
    CountDownLatch release = new CountDownLatch(1);
    Recorder stuckHeard = new Recorder();
    Recorder healthy = new Recorder();
    ExecutorService stuckThread = Executors.newSingleThreadExecutor();
    ExecutorService healthyThread = Executors.newSingleThreadExecutor();
    Receiver stuck = receiver("a", List.of(), (a, from, answer) -> {
      stuckHeard.heard(a, from, answer);
      try {
        release.await(); // its container is busy elsewhere
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }, stuckHeard, stuckThread);
    Receiver b = receiver("b", List.of(), healthy, healthy, healthyThread);
    try (DatagramChannel sender = LoopbackMulticast.sender()) {
      stuck.start(StandardProtocolFamily.INET, target, lo); // first: handed each datagram first
      b.start(StandardProtocolFamily.INET, target, lo);
      sender.send(ByteBuffer.wrap(announcement("other", 1).encode(KEY)), target);
      stuckHeard.awaitHeard("other", 1);
      sender.send(ByteBuffer.wrap(announcement("other", 2).encode(KEY)), target);
      healthy.awaitHeard("other", 2);
      assertEquals(1, stuckHeard.heardFrom("other"), "still stuck on the first");
      release.countDown();
      stuckHeard.awaitHeard("other", 2); // what waited for it is handled, nothing lost
    } finally {
      release.countDown();
      stuck.close();
      b.close();
      stuckThread.shutdown();
      healthyThread.shutdown();
    }
  }

  @Test
  void aReceiverFailingOnManyDatagramsInARowStopsNeitherItselfNorTheOthers() throws Exception {
    InetSocketAddress target = new InetSocketAddress(LoopbackMulticast.randomGroup(),
        LoopbackMulticast.freePort());
    List<NetworkInterface> lo = List.of(LoopbackMulticast.loopback());
    Failing failing = new Failing();
    Recorder failingHeard = new Recorder();
    Recorder healthy = new Recorder();
    Receiver a = receiver("a", List.of(), failingHeard, failing);
    Receiver b = receiver("b", List.of(), healthy, healthy);
    try (DatagramChannel sender = LoopbackMulticast.sender()) {
      a.start(StandardProtocolFamily.INET, target, lo);
      b.start(StandardProtocolFamily.INET, target, lo);
      int bad = 25; // the socket's reading thread used to stop after 10 failures in a row
      for (int i = 0; i < bad; i++) {
        sender.send(ByteBuffer.wrap(new byte[] {'n', 'o', 'i', 's', 'e'}), target);
      }
      healthy.await("all bad datagrams dropped", () -> healthy.dropsOtherThanOwn() == bad);
      byte[] good = announcement("other", 1).encode(KEY);
      sender.send(ByteBuffer.wrap(good), target);
      healthy.awaitHeard("other", 1);
      failingHeard.awaitHeard("other", 1);
      assertEquals(bad, failing.thrown.get(), "the failing receiver saw every bad datagram");
    } finally {
      a.close();
      b.close();
    }
  }

  /** Counts the warnings and errors discovery logs: here, receive failures (no other trace). */
  private static final class Failures extends Handler implements AutoCloseable {
    private final Logger logger = Logger.getLogger(Discovery.class.getName());
    private int count; // guarded by this

    Failures() {
      logger.addHandler(this);
    }

    @Override
    public synchronized void publish(LogRecord r) {
      if (r.getLevel().intValue() >= Level.WARNING.intValue()) {
        count++;
        notifyAll();
      }
    }

    synchronized void await(int n) throws InterruptedException {
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
      while (count < n) {
        long left = TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime());
        if (left <= 0) {
          fail("not within 5 s: " + n + " failures logged, only " + count);
        }
        wait(left);
      }
    }

    @Override
    public void flush() {}

    @Override
    public void close() {
      logger.removeHandler(this);
    }
  }

  @Test
  void aSocketThatFailsToReceiveManyTimesInARowIsRetriedUntilItWorks() throws Exception {
    InetSocketAddress target = new InetSocketAddress(LoopbackMulticast.randomGroup(),
        LoopbackMulticast.freePort());
    Recorder heard = new Recorder();
    try (DatagramChannel answers = DatagramChannel.open(StandardProtocolFamily.INET);
        DatagramChannel sender = LoopbackMulticast.sender();
        Failures failures = new Failures()) {
      // An answer channel connected to a port where nothing listens: each datagram it sends comes
      // back as "port unreachable", and its next receive fails with PortUnreachableException.
      answers.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
      answers.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(),
          LoopbackMulticast.freePort()));
      Receiver r = receiver("me", List.of(answers), heard, heard);
      r.start(StandardProtocolFamily.INET, target, List.of(LoopbackMulticast.loopback()));
      try {
        for (int i = 1; i <= 10; i++) { // the thread used to end after 10 in a row
          answers.write(ByteBuffer.wrap(new byte[] {1}));
          failures.await(i);
        }
        byte[] good = announcement("other", 1).encode(KEY);
        sender.send(ByteBuffer.wrap(good), target);
        heard.awaitHeard("other", 1);
      } finally {
        r.close();
      }
    }
  }
}
