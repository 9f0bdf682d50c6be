package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A slow link that carries everything in the end is not a dead one: neither side may declare the
 * other gone while bytes keep going across, however long a frame or a queue of frames takes.
 * Both sides here have {@code FAILURETIMEOUT=2000}: a frame takes a quarter of it or less on the
 * wire, so a machine too busy to run the throttling proxy for a moment does not close the link.
 */
class SlowLinkTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private static final String FAILURE_TIMEOUT = "2000";

  /** A provided service. */
  public static final class Digest {
    @TRADEService
    public byte[] sha256(byte[] data) {
      return ConcurrentCallersTest.sha256(data);
    }
  }

  /** What a test does with the provider's {@code sha256}, seen from the far side of the link. */
  private interface OverTheLink {
    void run(TRADEServiceInfo sha256) throws Exception;
  }

  /**
   * Runs {@code test} in a caller that reaches the provider through a proxy that passes
   * {@code bytesPerSecond} towards the provider (replies unthrottled); returns its time in ms.
   */
  private static long overASlowLink(long bytesPerSecond, OverTheLink test) throws Exception {
    try (TRADEContainer provider = Hubs.hubBuilder("far-provider")
        .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", FAILURE_TIMEOUT).build()) {
      provider.registerAllServices(new Digest());
      InetSocketAddress target = new InetSocketAddress("127.0.0.1",
          Integer.parseInt(provider.getServerAddresses().get(0).split("@")[1]));
      try (ThrottlingProxy slowLink = new ThrottlingProxy(target, bytesPerSecond);
          TRADEContainer caller = TRADEContainer.builder().name("far-caller")
              .property("HEARTBEATINTERVAL", "100").property("FAILURETIMEOUT", FAILURE_TIMEOUT)
              .property("CONNECTCONTAINERS", slowLink.address()).build()) {
        TRADEServiceConstraints sha = new TRADEServiceConstraints().name("sha256");
        Await.until(WAIT, () -> !caller.getAvailableServices(sha).isEmpty(), "the sha256 service");
        TRADEServiceInfo service = caller.getAvailableService(sha);
        long start = System.nanoTime();
        test.run(service);
        return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
      }
    }
  }

  /** The receiver must not declare the sender gone in the middle of a frame whose bytes keep coming. */
  @Test
  void largeArgumentSlowerThanTheFailureTimeoutArrives() throws Exception {
    byte[] data = new byte[6 << 20];
    new Random(7).nextBytes(data);
    // 6 MiB at 1 MiB/s: about six seconds on the wire, three failure timeouts.
    long ms = overASlowLink(1 << 20, sha256 ->
        assertArrayEquals(ConcurrentCallersTest.sha256(data), sha256.call(byte[].class, (Object) data)));
    System.out.println("6 MiB over a 1 MiB/s link with FAILURETIMEOUT=2000: " + ms + " ms");
    assertTrue(ms >= 4800, "the link was not slow: " + ms + " ms");
  }

  /**
   * Calls queued faster than a slow link carries them are written one after the other: each write
   * goes on, so none has waited FAILURETIMEOUT, however long the whole queue takes to drain. The
   * sender must not close the link as "not reading" while the peer reads all along.
   */
  @Test
  void aQueueThatTakesLongerThanTheFailureTimeoutToDrainIsNotAStalledWrite() throws Exception {
    // 16 calls of 1 MiB at once over a 2 MiB/s link: each frame takes half a second, the queue
    // of them (beyond what socket buffers hold) several FAILURETIMEOUTs.
    long ms = overASlowLink(2 << 20, sha256 -> {
      List<CompletableFuture<Boolean>> calls = new ArrayList<>();
      for (int i = 0; i < 16; i++) {
        byte[] data = new byte[1 << 20];
        new Random(i).nextBytes(data);
        calls.add(CompletableFuture.supplyAsync(() -> {
          try {
            return java.util.Arrays.equals(ConcurrentCallersTest.sha256(data),
                sha256.call(byte[].class, (Object) data));
          } catch (Exception e) {
            throw new IllegalStateException(e);
          }
        }, runnable -> new Thread(runnable).start()));
      }
      for (CompletableFuture<Boolean> call : calls) {
        assertTrue(call.get(60, TimeUnit.SECONDS));
      }
    });
    System.out.println("16 x 1 MiB over a 2 MiB/s link with FAILURETIMEOUT=2000: " + ms + " ms");
    assertTrue(ms >= 6000, "the link was not slow: " + ms + " ms");
  }

  /**
   * A caller whose thread happens to write for everyone (it found the link idle) stops writing for
   * the others in time: while other callers keep a slow link busy, no call may outlast its deadline
   * by more than a moment, the writing one's included.
   */
  @Test
  void noCallerIsHeldWritingForOthersPastItsDeadline() throws Exception {
    long timeoutMs = 1500;
    List<Long> durations = java.util.Collections.synchronizedList(new ArrayList<>());
    overASlowLink(2 << 20, sha256 -> {
      TRADEServiceInfo timed = sha256.withTimeout(Duration.ofMillis(timeoutMs));
      long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(4);
      List<Thread> callers = new ArrayList<>();
      for (int t = 0; t < 8; t++) {
        Thread caller = new Thread(() -> {
          byte[] data = new byte[1 << 20];
          while (System.nanoTime() < until) {
            long start = System.nanoTime();
            try {
              timed.call(byte[].class, (Object) data);
            } catch (Exception e) {
              // Timeouts are expected on a link this busy; how long each call took is the point.
            }
            durations.add(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start));
          }
        });
        caller.start();
        callers.add(caller);
      }
      for (Thread caller : callers) {
        caller.join(60_000);
      }
    });
    long longest = durations.stream().mapToLong(Long::longValue).max().orElse(0);
    System.out.println(durations.size() + " calls of 1 MiB over a 2 MiB/s link, timeout "
        + timeoutMs + " ms: the longest took " + longest + " ms");
    assertTrue(longest < timeoutMs + 1500, "a call took " + longest + " ms");
  }
}
