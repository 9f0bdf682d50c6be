package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.net.link.Wire;
import dev.trade.testing.Await;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A peer that authenticates and then says nothing is declared gone after FAILURETIMEOUT, while a
 * live but idle neighbour is kept by its heartbeats.
 */
@Timeout(60)
class SilentPeerTest {
  private final LogCapture log = new LogCapture();
  private TRADEContainer server;

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  @AfterEach
  void close() {
    if (server != null) {
      server.close();
    }
    log.close();
  }

  private InetSocketAddress start(TRADEContainer.Builder builder) {
    server = builder.name("listener").property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0").build();
    String[] a = server.getServerAddresses().get(0).split("@");
    return new InetSocketAddress(a[0], Integer.parseInt(a[1]));
  }

  /** How long after the handshake the server closed a peer that never sent a frame. */
  private Duration silence(InetSocketAddress address, Duration bound) throws Exception {
    try (RawPeer mute = RawPeer.connect(address)) {
      mute.handshake("mute");
      return mute.awaitClosed(bound);
    }
  }

  @Test
  void silentPeerIsClosedAfterFailureTimeout() throws Exception {
    InetSocketAddress address = start(TRADEContainer.builder()
        .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "600"));
    Duration took = silence(address, Duration.ofSeconds(20)); // a bound for a busy machine
    assertTrue(took.toMillis() >= 550, "closed after " + took.toMillis() + " ms, before FAILURETIMEOUT");
    Await.until(Duration.ofSeconds(5), () -> log.has(Level.INFO,
        "listener: link to mute closed: silent for", "ms (FAILURETIMEOUT=600)"), "the reason in:\n" + log.tail());
  }

  @Test
  void withDefaultSettingsTheBoundIsThreeSeconds() throws Exception {
    InetSocketAddress address = start(TRADEContainer.builder());
    // FAILURETIMEOUT=3000 is the bound itself, not 3000 plus a HEARTBEATINTERVAL (1000): that is
    // HeartbeatTest's, on times it chooses; here a busy machine may take longer.
    Duration took = silence(address, Duration.ofSeconds(20));
    assertTrue(took.toMillis() >= 2_900, "closed after " + took.toMillis() + " ms, before FAILURETIMEOUT");
  }

  @Test
  void aNewLinkIsPingedAtOnceNotAtTheNextBeat() throws Exception {
    // Beats a minute apart: a PING within 30 s can only be the one sent as the link came up.
    InetSocketAddress address = start(TRADEContainer.builder().property("HEARTBEATINTERVAL", "60000")
        .property("FAILURETIMEOUT", "180000"));
    try (RawPeer p = RawPeer.connect(address)) {
      p.handshake("new");
      long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
      boolean pinged = false;
      while (!pinged && System.nanoTime() - deadline < 0) {
        pinged = p.readFrame()[0] == Wire.PING; // the peer's LINKS and TABLE come too
      }
      assertTrue(pinged, "no PING on the new link within 30 s");
    }
  }

  @Test
  void heartbeatsKeepAnIdleLinkAlive() throws TRADEException {
    start(TRADEContainer.builder().property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "600"));
    try (TRADEContainer idle = TRADEContainer.builder().name("idle")
        .property("CONNECTCONTAINERS", server.getServerAddresses().get(0))
        .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "600").build()) {
      server.registerAllServices(new Arm());
      TRADEServiceConstraints open = new TRADEServiceConstraints().name("openGripper");
      Await.until(Duration.ofSeconds(10), () -> !idle.getAvailableServices(open).isEmpty(), "the link");
      // Idle for five failure timeouts, watching for the link's closure: only heartbeats cross.
      long end = System.nanoTime() + Duration.ofMillis(3_000).toNanos();
      Await.until(Duration.ofSeconds(5), () -> System.nanoTime() - end > 0
          || log.has(Level.INFO, "link to idle closed"), "3 s of idleness");
      assertFalse(log.has(Level.INFO, "link to idle closed"), log.tail());
      assertTrue(idle.getAvailableService(open).call(boolean.class, 3));
    }
  }
}
