package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.testing.Await;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/**
 * DISCOVERYCLOCKSKEW reaches each container's discovery: an announcement from a host whose clock
 * is an hour behind is dropped, with the advice in the log, by a container with the default
 * tolerance, and heard, so its sender dialled, by one with the check off. Two containers of one
 * JVM, which share the group's socket; loopback, TTL 0, inside the CI's private network namespace.
 */
class ClockSkewSettingTest {
  private static final long HOUR_MS = 3_600_000L;

  @Test
  void aContainerWithTheClockCheckOffHearsAHostWhoseClockIsAnHourBehind() throws IOException {
    LoopbackMulticast.assumeUsable();
    InetAddress group = LoopbackMulticast.randomGroup();
    int port = LoopbackMulticast.freePort();
    List<String> lines = new CopyOnWriteArrayList<>();
    Handler capture = new Handler() {
      @Override
      public void publish(LogRecord r) {
        lines.add(new java.util.logging.SimpleFormatter().formatMessage(r));
      }

      @Override
      public void flush() {}

      @Override
      public void close() {}
    };
    Logger log = Logger.getLogger(Discovery.class.getName());
    log.addHandler(capture);
    try (ServerSocket skewedHost = new ServerSocket(0, 5, InetAddress.getLoopbackAddress());
        TRADEContainer tolerant = container("tolerant", group, port, "0");
        TRADEContainer strict = container("strict", group, port, "30000");
        DatagramChannel sender = LoopbackMulticast.sender()) {
      Announcement behind = new Announcement(1, Fixtures.SYSTEM, UUID.randomUUID().toString(),
          "skewed", List.of((InetSocketAddress) skewedHost.getLocalSocketAddress()), 1,
          System.currentTimeMillis() - HOUR_MS);
      sender.send(ByteBuffer.wrap(behind.encode(Fixtures.KEY)), new InetSocketAddress(group, port));

      skewedHost.setSoTimeout(10_000); // a deadline, not a pause: accept returns at the dial
      try (Socket dialled = skewedHost.accept()) {
        assertTrue(dialled.getInetAddress().isLoopbackAddress());
      }
      Await.until(Duration.ofSeconds(10), () -> lines.stream().anyMatch(
              l -> l.contains("behind our clock") && l.contains("set DISCOVERYCLOCKSKEW")),
          "the strict container's CLOCK_SKEW line, in " + lines);
    } finally {
      log.removeHandler(capture);
    }
  }

  private static TRADEContainer container(String name, InetAddress group, int port, String skew) {
    return TRADEContainer.builder().name(name)
        .property("STARTDISCOVERY", "true").property("STARTBROADCAST", "false")
        .property("MCAST_ADDR", group.getHostAddress())
        .property("BROADCASTPORT", Integer.toString(port))
        .property("TRADESYSID", Fixtures.SYSTEM).property("CREDENTIALS", "s3cret")
        .property("DISCOVERYCLOCKSKEW", skew).build();
  }
}
