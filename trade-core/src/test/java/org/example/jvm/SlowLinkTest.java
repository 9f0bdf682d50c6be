package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.example.net.Await;
import org.junit.jupiter.api.Test;

/**
 * A frame that takes longer than {@code FAILURETIMEOUT} to arrive over a slow link is not silence:
 * its bytes keep arriving, so the receiver must not declare the sender gone in the middle of it.
 */
class SlowLinkTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** A provided service. */
  public static final class Digest {
    @TRADEService
    public byte[] sha256(byte[] data) {
      return ConcurrentCallersTest.sha256(data);
    }
  }

  @Test
  void largeArgumentSlowerThanTheFailureTimeoutArrives() throws Exception {
    try (TRADEContainer provider = TRADEContainer.builder().name("far-provider")
        .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "800")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0").build()) {
      provider.registerAllServices(new Digest());
      InetSocketAddress target = new InetSocketAddress("127.0.0.1",
          Integer.parseInt(provider.getServerAddresses().get(0).split("@")[1]));
      // 3 MiB at 1 MiB/s: about three seconds on the wire, more than three failure timeouts.
      try (ThrottlingProxy slowLink = new ThrottlingProxy(target, 1 << 20);
          TRADEContainer caller = TRADEContainer.builder().name("far-caller")
              .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", "800")
              .property("CONNECTCONTAINERS", slowLink.address()).build()) {
        TRADEServiceConstraints sha = new TRADEServiceConstraints().name("sha256");
        Await.until(WAIT, () -> !caller.getAvailableServices(sha).isEmpty(), "the sha256 service");
        byte[] data = new byte[3 << 20];
        new Random(7).nextBytes(data);
        long start = System.nanoTime();
        byte[] digest = caller.getAvailableService(sha).call(byte[].class, (Object) data);
        long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        System.out.println("3 MiB over a 1 MiB/s link with FAILURETIMEOUT=800: " + ms + " ms");
        assertArrayEquals(ConcurrentCallersTest.sha256(data), digest);
        assertTrue(ms >= 2400, "the link was not slow: " + ms + " ms");
      }
    }
  }
}
