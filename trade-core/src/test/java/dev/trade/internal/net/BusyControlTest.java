package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.config.Settings;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.time.Scheduler;
import java.time.Duration;
import java.util.Properties;
import java.util.UUID;
import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A link is read and kept alive from its handshake on, even while the control thread, which
 * registers it, is busy: with 100 containers that thread ran seconds behind, and peers closed the
 * links it had not got to yet as silent.
 */
@Timeout(30)
class BusyControlTest {
  /** The containers' clock and timer (a container owns one; these networks share it). */
  private static final Scheduler SCHEDULER = Scheduler.system("test");

  @AfterAll
  static void stopTimer() {
    SCHEDULER.close();
  }

  @Test
  void aNewLinkIsReadAndPingedWhileTheControlThreadIsBusy() throws Exception {
    Properties p = new Properties();
    p.setProperty("STARTACCEPTINGCONNECTIONS", "true");
    p.setProperty("SERVERIPS", "127.0.0.1@0");
    p.setProperty("HEARTBEATINTERVAL", "100");
    p.setProperty("FAILURETIMEOUT", "1000");
    UUID id = UUID.randomUUID();
    Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
    CountDownLatch release = new CountDownLatch(1);
    try (Network net = new Network(Settings.fromProperties(p), id, "busy", "host",
        new Registry(id.toString(), "busy", "host"), codec, codec, null, SCHEDULER)) {
      net.start();
      ControlThread.block(net, release);
      try (RawPeer peer = RawPeer.connect(net.listenAddresses().get(0))) {
        peer.handshake("newcomer");
        // Over twice FAILURETIMEOUT: the container pings the link, and reads ours (else it would
        // close the link as silent, and readFrame would fail).
        long until = System.nanoTime() + Duration.ofMillis(2_500).toNanos();
        int pings = 0;
        while (System.nanoTime() - until < 0) {
          byte[] frame = peer.readFrame();
          assertEquals(Wire.PING, frame[0], "only pings while the control thread is blocked");
          pings++;
          peer.send(RawPeer.frame(Wire.PING, new byte[0]));
        }
        assertTrue(pings >= 5, "pings: " + pings);
        release.countDown();
        // Once the control thread is free, the link is registered: the container's link state
        // follows.
        long deadline = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        byte[] frame;
        do {
          frame = peer.readFrame();
        } while (frame[0] != Wire.LINKS && System.nanoTime() - deadline < 0);
        assertEquals(Wire.LINKS, frame[0]);
      } finally {
        release.countDown();
      }
    }
  }
}
