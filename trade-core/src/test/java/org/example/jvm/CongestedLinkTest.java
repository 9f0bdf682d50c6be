package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.TRADETimeoutException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Calls made faster than a link carries them queue up to a bound (16 MiB not yet written); beyond
 * it a caller waits for room, until its deadline, and a container passing calls on answers "not
 * available now", instead of the queue growing without end. Here the link's far end takes nothing
 * for a while (a proxy in between stops passing bytes), with FAILURETIMEOUT long enough that the
 * link stays up meanwhile.
 */
@Timeout(60)
class CongestedLinkTest {
  private static final int CALLS = 48;

  /** {@code sha256}, counting the calls it serves. */
  public static final class CountingDigest {
    final AtomicInteger served = new AtomicInteger();

    @TRADEService
    public byte[] sha256(byte[] data) {
      served.incrementAndGet();
      return ConcurrentCallersTest.sha256(data);
    }
  }

  private final CountingDigest digest = new CountingDigest();

  /** A provider of {@code sha256} in group "far", behind a proxy that takes nothing when paused. */
  private TRADEContainer provider() throws TRADEException {
    TRADEContainer provider = Hubs.hubBuilder("far-provider")
        .property("FAILURETIMEOUT", "30000").build();
    provider.registerAllServices(digest, "far");
    return provider;
  }

  private static InetSocketAddress address(TRADEContainer c) {
    return new InetSocketAddress("127.0.0.1",
        Integer.parseInt(c.getServerAddresses().get(0).split("@")[1]));
  }

  private static TRADEServiceInfo await(TRADEContainer caller, String group) throws Exception {
    TRADEServiceConstraints sha = new TRADEServiceConstraints().name("sha256").inGroups(group);
    Await.until(Duration.ofSeconds(10), () -> !caller.getAvailableServices(sha).isEmpty(),
        "sha256 of " + group + " at " + caller.getName());
    return caller.getAvailableService(sha);
  }

  /**
   * Makes {@link #CALLS} calls of 1 MiB at once while the proxy takes nothing, then lets it take
   * bytes again once every call but one has ended (the one whose thread writes is held in a socket
   * write the far end does not take); returns the texts of the calls that failed so.
   */
  private static List<Throwable> congest(ThrottlingProxy proxy, TRADEServiceInfo sha256)
      throws Exception {
    proxy.pause();
    List<CompletableFuture<Object>> calls = new ArrayList<>();
    for (int i = 0; i < CALLS; i++) {
      calls.add(CompletableFuture.supplyAsync(() -> {
        try {
          return sha256.call(byte[].class, (Object) new byte[1 << 20]);
        } catch (Exception e) {
          throw new IllegalStateException(e);
        }
      }, runnable -> new Thread(runnable).start()));
    }
    Await.until(Duration.ofSeconds(15),
        () -> calls.stream().filter(CompletableFuture::isDone).count() >= CALLS - 1,
        "all calls but the writing one to end");
    // A container passing a call on counts its time from when the call reached it, so its view of
    // a call's time runs out after the caller's, by the time the call took to get there: 48 MiB
    // of calls cross the caller's link first, which can take a few hundred ms on a busy machine.
    // The queued calls are all out of time for everyone once a second more has passed.
    long givenUp = System.nanoTime();
    Await.until(Duration.ofSeconds(5),
        () -> System.nanoTime() - givenUp > TimeUnit.SECONDS.toNanos(1), "a second to pass");
    proxy.resume();
    List<Throwable> failures = new ArrayList<>();
    for (CompletableFuture<Object> call : calls) {
      try {
        call.get(20, TimeUnit.SECONDS);
      } catch (ExecutionException e) {
        failures.add(e.getCause().getCause());
      }
    }
    return failures;
  }

  @Test
  void aCongestedLinkHoldsBackNewCallsAndLeavesOutThoseGivenUpOn() throws Exception {
    try (TRADEContainer provider = provider();
        ThrottlingProxy proxy = new ThrottlingProxy(address(provider), 0);
        TRADEContainer caller = TRADEContainer.builder().name("near-caller")
            .property("FAILURETIMEOUT", "30000")
            .property("CONNECTCONTAINERS", proxy.address()).build()) {
      TRADEServiceInfo sha256 = await(caller, "far").withTimeout(Duration.ofSeconds(3));
      int waitedForRoom = 0;
      for (Throwable failure : congest(proxy, sha256)) {
        assertTrue(failure instanceof TRADETimeoutException, failure.toString());
        if (failure.getMessage().contains("waited all that time to be sent")) {
          waitedForRoom++;
          assertTrue(failure.getMessage().endsWith(
              "that far-provider takes slower than they are sent"), failure.getMessage());
        }
      }
      System.out.println(waitedForRoom + " of " + CALLS + " calls of 1 MiB waited for room");
      // At most what socket buffers hold (a few MiB each way on loopback) plus 16 MiB got out.
      assertTrue(waitedForRoom >= 8, waitedForRoom + " calls waited for room");
      // The far end takes bytes again, and calls go through: the link never closed.
      assertEquals(32, sha256.withTimeout(Duration.ofSeconds(30))
          .call(byte[].class, (Object) new byte[16]).length);
      // The calls still queued when their callers gave up were left out: the provider served only
      // those already on their way (in socket buffers), and the last one. Each call it served
      // started before the last one was read.
      int queued = CALLS - waitedForRoom;
      int served = digest.served.get() - 1;
      System.out.println(served + " of the " + queued + " calls that were queued reached the provider");
      assertTrue(served <= queued - 8, served + " of " + queued + " queued calls were served");
    }
  }

  /**
   * A container that passes calls on to a link without room answers them "not available now" at
   * once, and goes on reading the link they came over: calls to that container itself are not held
   * up behind them.
   */
  @Test
  void aForwarderAnswersNotAvailableNowWhenTheLinkOnwardHasNoRoom() throws Exception {
    try (TRADEContainer provider = provider();
        ThrottlingProxy proxy = new ThrottlingProxy(address(provider), 0);
        TRADEContainer hub = Hubs.hubBuilder("hub").property("FAILURETIMEOUT", "30000")
            .property("CONNECTCONTAINERS", proxy.address()).build();
        TRADEContainer caller = Hubs.spokeBuilder("caller", hub).build()) {
      hub.registerAllServices(new SlowLinkTest.Digest(), "hub");
      TRADEServiceInfo near = await(caller, "hub").withTimeout(Duration.ofSeconds(2));
      TRADEServiceInfo far = await(caller, "far").withTimeout(Duration.ofSeconds(5));
      CompletableFuture<List<Throwable>> congested = CompletableFuture.supplyAsync(() -> {
        try {
          return congest(proxy, far);
        } catch (Exception e) {
          throw new IllegalStateException(e);
        }
      });
      // Meanwhile, calls to the hub itself still go through.
      Await.until(Duration.ofSeconds(10), () -> proxy.isPaused(), "the proxy to stop");
      assertEquals(32, near.call(byte[].class, (Object) new byte[16]).length);
      int notNow = 0;
      for (Throwable failure : congested.get(40, TimeUnit.SECONDS)) {
        if (failure.getMessage().startsWith("Service not available now: the link from ")) {
          notNow++;
          assertTrue(failure instanceof TRADEServiceUnavailableException, failure.toString());
        }
      }
      System.out.println(notNow + " of " + CALLS + " forwarded calls of 1 MiB: not available now");
      assertTrue(notNow >= 8, notNow + " forwarded calls answered not available now");
      // The hub, too, left out the calls still queued when their callers gave up: it counts their
      // time from when each came in.
      Await.until(Duration.ofSeconds(20), () -> {
        try { // once the hub's queue has drained
          return far.withTimeout(Duration.ofSeconds(10)).call(byte[].class, (Object) new byte[16])
              .length == 32;
        } catch (TRADEException e) {
          return false;
        }
      }, "a call through the hub once its queue drained");
      int passedOn = CALLS - notNow;
      int served = digest.served.get() - 1;
      System.out.println(served + " of the " + passedOn + " calls the hub took reached the provider");
      assertTrue(served <= passedOn - 8, served + " of " + passedOn + " calls passed on were served");
    }
  }
}
