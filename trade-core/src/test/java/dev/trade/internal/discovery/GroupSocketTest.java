package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.KEY;
import static dev.trade.internal.discovery.Fixtures.SYSTEM;
import static dev.trade.internal.discovery.Fixtures.announcement;
import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.StandardProtocolFamily;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The shared group socket keeps delivering whatever one of its receivers does (loopback, TTL 0). */
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

  private static Receiver receiver(String id, Discovery.Listener listener, Receiver.Observer observer) {
    return new Receiver(List.of(), SYSTEM, id, KEY, listener, from -> { }, observer,
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
    Receiver a = receiver("a", failingHeard, failing);
    Receiver b = receiver("b", healthy, healthy);
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
}
