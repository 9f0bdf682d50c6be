package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.config.Settings;
import dev.trade.internal.discovery.LoopbackMulticast;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.time.Scheduler;
import dev.trade.testing.Await;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.time.Duration;
import java.util.Properties;
import java.util.UUID;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A container does not dial a container whose handshake with it is under way. Its side of a new
 * link is registered only when its control thread gets to it, seconds later in a loaded JVM; a
 * dial meanwhile made a second link, which one side then closed as a duplicate (in 100-container
 * runs with timely discovery, 220 such links until convergence, against about 50).
 */
@Timeout(60)
class LinkingPeerNotDialledTest {
  /** The containers' clock and timer (a container owns one; these networks share it). */
  private static final Scheduler SCHEDULER = Scheduler.system("test");

  @AfterAll
  static void stopTimer() {
    SCHEDULER.close();
  }

  private static final Duration WAIT = Duration.ofSeconds(10);

  @BeforeEach
  void multicast() {
    LoopbackMulticast.assumeUsable();
  }

  @Test
  void aContainerBehindOnItsControlThreadDoesNotDialThePeerLinkingToIt() throws Exception {
    String system = "linking-" + UUID.randomUUID();
    Properties p = discovering(system);
    // Ordered as unsigned numbers: "low" dials at once, "high" only if no link appeared 300 ms
    // after it chose "low" (Finder.dialsAtOnce).
    UUID low = new UUID(0x1000_0000_0000_0000L, 1);
    UUID high = new UUID(0x7000_0000_0000_0000L, 2);
    CountDownLatch release = new CountDownLatch(1);
    try (LogCapture log = new LogCapture(); Network b = network(p, high, "high")) {
      b.start();
      ControlThread.block(b, release);
      try (Network a = network(p, low, "low")) {
        a.start();
        Await.until(WAIT, () -> a.neighbours().contains(high.toString()),
            "low to link to high (on low's side)");
        // "high" chooses "low" as soon as it hears it, and dials it (300 ms later) unless discovery
        // counts it as linked: with its control thread blocked, only the handshake says so.
        assertFalse(b.neighbours().contains(low.toString()), "high's control thread is blocked");
        assertTrue(b.linkedOrLinking(low), "high counts the link from low under way as a link");
        release.countDown();
        Await.until(WAIT, () -> b.neighbours().contains(low.toString()),
            "high to register the link once its control thread is free");
        assertFalse(log.has(Level.FINE, "closed a duplicate link"), log.tail());
      }
    } finally {
      release.countDown();
    }
  }

  private static Properties discovering(String system) throws Exception {
    Properties p = new Properties();
    p.setProperty("STARTACCEPTINGCONNECTIONS", "true");
    p.setProperty("SERVERIPS", "127.0.0.1@0");
    p.setProperty("STARTDISCOVERY", "true");
    p.setProperty("STARTBROADCAST", "true");
    p.setProperty("DISCOVERYRANGE", "localhost");
    p.setProperty("TRADESYSID", system);
    p.setProperty("MCAST_ADDR", "239.255." + ThreadLocalRandom.current().nextInt(256) + "."
        + (1 + ThreadLocalRandom.current().nextInt(254)));
    try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
      p.setProperty("BROADCASTPORT", Integer.toString(s.getLocalPort()));
    }
    return p;
  }

  private static Network network(Properties p, UUID id, String name) {
    Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
    return new Network(Settings.fromProperties(p), id, name, "host",
        new Registry(id.toString(), name, "host"), codec, codec, null, SCHEDULER);
  }
}
