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
    return new Receiver(answers, SYSTEM, id, KEY, listener, (a, from) -> { }, observer,
        Duration.ofSeconds(30), Duration.ofSeconds(60), true);
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
