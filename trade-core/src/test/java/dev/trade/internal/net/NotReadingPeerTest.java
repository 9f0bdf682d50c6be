package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.time.Duration;
import java.util.Arrays;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A peer that goes on pinging but stops reading: once its socket buffers are full, a write to it
 * waits for good, and with it whoever writes. Here that is the container's control thread, which
 * answers the peer's requests for its table: stalled, it would apply no link state or table of
 * any other container again, and the peer's pings keep the link from looking silent. The heartbeat
 * closes a link whose write has waited for FAILURETIMEOUT, which ends the write. On loopback.
 */
class NotReadingPeerTest {
  private static final byte[] PING = Frames.finish(Frames.start(Wire.PING, 0));

  public static class Probe {
    @TRADEService
    public int probe() {
      return 7;
    }
  }

  @Test
  @Timeout(180)
  void aLinkWhosePeerStopsReadingIsClosedOnceAWriteHasWaitedForFailureTimeout() throws Exception {
    ScheduledExecutorService pinger = Executors.newSingleThreadScheduledExecutor();
    try (LogCapture log = new LogCapture();
        TRADEContainer provider = accepting("provider")
            .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "1500").build()) {
      provider.registerAllServices(new Probe());
      try (RawPeer sink = RawPeer.connect(provider)) {
        sink.handshake("sink");
        // Alive by its heartbeats all along: only a stalled write can end the link.
        pinger.scheduleAtFixedRate(() -> sink.send(PING), 0, 50, TimeUnit.MILLISECONDS);
        // Requests for the provider's table, whose answers come to far more than loopback's
        // socket buffers (a few MB each way) hold, and are never read.
        sink.send(tableRequests(provider.getId(), 200_000));
        // 200,000 answers take a while to make on a busy machine before the buffers are full.
        Await.until(Duration.ofSeconds(120), () -> log.has(Level.INFO,
            "provider: link to sink closed: not reading: a write has waited", "(FAILURETIMEOUT=1500)"),
            "the link closed for its stalled write, in:\n" + log.tail());
      }
      // The control thread is free again: the container still works.
      assertEquals(7, provider.getAvailableService(new TRADEServiceConstraints().name("probe"))
          .call(Integer.class));
    } finally {
      pinger.shutdownNow();
    }
  }

  /**
   * A member that sends replication frames faster than they can be applied, here table requests
   * whose answers it never reads (so that the control thread, stalled on writing one, applies
   * nothing), is cut off once its backlog passes the limit, long before FAILURETIMEOUT, rather than
   * filling the container's memory. The limit is two of the largest frames, at least 16 MiB.
   */
  @Test
  @Timeout(60)
  void aMemberWhoseReplicationFramesPileUpUnappliedIsCutOff() throws Exception {
    try (LogCapture log = new LogCapture();
        TRADEContainer provider = accepting("flooded")
            // Frames small enough that the limit is its floor, 16 MiB; not the smallest settings
            // (1 or 4 KiB), which the container's own table (its system services among it) does
            // not fit.
            .property("MAXFRAMESIZE", "65536").property("FAILURETIMEOUT", "60000").build()) {
      provider.registerAllServices(new Probe());
      try (RawPeer sink = RawPeer.connect(provider)) {
        sink.handshake("flooder");
        // 300,000 x (45 + 128) bytes held: 52 MB
        sink.send(tableRequests(provider.getId(), 300_000));
        Await.until(Duration.ofSeconds(30), () -> log.has(Level.INFO,
            "flooded: link to flooder closed: connection to flooder lost: flooding: more than"
            + " 16777216 bytes of its replication frames wait to be applied here"),
            "the link closed for flooding, in:\n" + log.tail());
      }
      assertEquals(7, provider.getAvailableService(new TRADEServiceConstraints().name("probe"))
          .call(Integer.class));
    }
  }

  /**
   * Closing a container whose neighbour has stopped reading: its goodbye, and whatever was being
   * written, cannot go out, and FAILURETIMEOUT (long here) has not passed. close() still returns
   * within its grace period, and lets go of the link: its socket, and the threads that were
   * writing to it or reading it.
   */
  @Test
  @Timeout(60)
  void closeLetsGoOfALinkWhosePeerStopsReadingWithinItsGracePeriod() throws Exception {
    TRADEContainer provider = accepting("closing")
        .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "30000").build();
    try (RawPeer sink = RawPeer.connect(provider)) {
      sink.handshake("stalled");
      sink.send(tableRequests(provider.getId(), 200_000));
      awaitStalledWrite(sink, "closing");
      long start = System.nanoTime();
      provider.close();
      Duration took = Duration.ofNanos(System.nanoTime() - start);
      // Its grace is 2 s; without it, close() would wait for FAILURETIMEOUT (30 s) or for good.
      assertTrue(took.compareTo(Duration.ofSeconds(15)) < 0, "close() took " + took);
      // The peer finds the connection gone when it next writes (reset), without reading.
      OutputStream out = sink.socket.getOutputStream();
      Await.until(Duration.ofSeconds(10), () -> {
        try {
          out.write(PING);
          out.flush();
          return false;
        } catch (IOException gone) {
          return true;
        }
      }, "the closed container's socket to the peer is closed");
      Await.until(Duration.ofSeconds(10), () -> Thread.getAllStackTraces().keySet().stream()
          .noneMatch(t -> t.getName().startsWith("trade-control-closing")
              || t.getName().equals("trade-link-stalled")),
          "the closed container's threads for the link have ended");
    }
  }

  /** A container that accepts connections on loopback; the test adds its other settings. */
  private static TRADEContainer.Builder accepting(String name) {
    return Hubs.hubBuilder(name);
  }

  /** {@code count} TABLE_REQUEST frames for the table of container {@code id}, back to back. */
  private static byte[] tableRequests(String id, int count) {
    byte[] request = StateFrames.tableRequest(id);
    ByteArrayOutputStream requests = new ByteArrayOutputStream(count * request.length);
    for (int i = 0; i < count; i++) {
      requests.writeBytes(request);
    }
    return requests.toByteArray();
  }

  /**
   * Waits until a thread whose name starts with {@code writer} is in a socket write while the
   * bytes the peer has not read stay the same for a hundred checks in a row: the write is stalled.
   */
  /**
   * Waits until a thread of container {@code container} is stuck writing to {@code peer}: the
   * control thread as it answers, or a worker whose ping took the link's write first (then the
   * control thread waits for it), whichever the machine's timing made it.
   */
  private static void awaitStalledWrite(RawPeer peer, String container) {
    long[] unread = {-1, 0};
    Await.until(Duration.ofSeconds(30), () -> {
      long now;
      try {
        now = peer.socket.getInputStream().available();
      } catch (IOException e) {
        throw new AssertionError(e);
      }
      boolean writing = Thread.getAllStackTraces().entrySet().stream()
          .anyMatch(e -> e.getKey().getName().startsWith("trade-")
              && e.getKey().getName().contains(container) && Arrays.stream(e.getValue())
              .anyMatch(f -> f.getMethodName().equals("implWrite")));
      unread[1] = writing && now > 0 && now == unread[0] ? unread[1] + 1 : 0;
      unread[0] = now;
      return unread[1] >= 100;
    }, "a write of " + container + " to stall");
  }
}
