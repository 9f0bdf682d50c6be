package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Calls are served on the thread that reads their link; what that must not cost: a service that
 * blocks does not hold up later calls over the same link, and a service that calls back into its
 * caller's container over that link gets its answer.
 */
class ServedOnTheLinkTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  public static class Gate {
    final CountDownLatch open = new CountDownLatch(1);
    final CountDownLatch entered = new CountDownLatch(1);

    @TRADEService
    public String passThrough(String who) throws InterruptedException {
      entered.countDown();
      open.await();
      return who;
    }

    @TRADEService
    public int twice(int x) {
      return 2 * x;
    }
  }

  /** Lives in the calling container; the hub's {@code relay} calls it back. */
  public static class Spoke {
    @TRADEService
    public String whoAmI() {
      return "spoke";
    }
  }

  public static class Relay {
    final TRADEContainer hub;

    Relay(TRADEContainer hub) {
      this.hub = hub;
    }

    @TRADEService
    public String relay() throws TRADEException {
      return "via hub: " + hub.getAvailableService(new TRADEServiceConstraints().name("whoAmI"))
          .call(String.class);
    }
  }

  @RegisterExtension final Hubs net = new Hubs();
  private final TRADEContainer hub = net.hub("hub");
  private final TRADEContainer spoke = net.spoke("spoke", hub);

  private static TRADEServiceInfo await(TRADEContainer c, String name) throws TRADEException {
    TRADEServiceConstraints constraints = new TRADEServiceConstraints().name(name);
    Await.until(WAIT, () -> !c.getAvailableServices(constraints).isEmpty(), name);
    return c.getAvailableService(constraints);
  }

  @Test
  void aBlockedServiceDoesNotHoldUpLaterCallsOnItsLink() throws Exception {
    Gate gate = new Gate();
    hub.registerAllServices(gate);
    TRADEServiceInfo pass = await(spoke, "passThrough");
    TRADEServiceInfo twice = await(spoke, "twice").withTimeout(WAIT);
    CompletableFuture<String> blocked = CompletableFuture.supplyAsync(() -> {
      try {
        return pass.call(String.class, "first");
      } catch (TRADEException e) {
        throw new IllegalStateException(e);
      }
    });
    assertEquals(true, gate.entered.await(WAIT.toSeconds(), TimeUnit.SECONDS));
    for (int i = 0; i < 100; i++) {
      assertEquals(2 * i, twice.call(int.class, i)); // over the link whose reader is blocked
    }
    assertEquals(1, gate.open.getCount(), "the first call is still blocked");
    gate.open.countDown();
    assertEquals("first", blocked.get(WAIT.toSeconds(), TimeUnit.SECONDS));
  }

  @Test
  void aServiceMayCallBackOverTheLinkItWasCalledOn() throws Exception {
    spoke.registerAllServices(new Spoke());
    hub.registerAllServices(new Relay(hub));
    await(hub, "whoAmI");
    TRADEServiceInfo relay = await(spoke, "relay").withTimeout(WAIT);
    for (int i = 0; i < 50; i++) {
      assertEquals("via hub: spoke", relay.call(String.class));
    }
  }
}
