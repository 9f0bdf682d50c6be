package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * A provider process killed with SIGKILL while calls to it are running: every caller gets the
 * unavailable error within a second, not a hang and not the call's deadline, and the provider's
 * services leave the caller's registry within a second too. Both ends of a link are covered: the
 * provider that accepted the connection, and the provider that dialled in.
 */
class KillProviderTest {
  private static final Duration START = Duration.ofSeconds(30);
  /**
   * A killed process's sockets end at once, and its calls fail then (typically within tens of ms;
   * the reliability suite's load part measures it). The bound leaves a loaded machine room and
   * stays far below the callers' deadline (30 s) and a silence's detection, which a minute's
   * FAILURETIMEOUT on the caller rules out.
   */
  private static final long LIMIT_MS = 10_000;
  private static final int CALLERS = 8;
  private static final TRADEServiceConstraints PROVIDED = new TRADEServiceConstraints().inGroups("provider");

  @Test
  void killedProviderThatAcceptedTheLink() throws Exception {
    try (JvmProcess provider = ProviderMain.launch(List.of(), "CONTAINERNAME=victim",
        "STARTACCEPTINGCONNECTIONS=true", "SERVERIPS=127.0.0.1@0")) {
      String address = ProviderMain.address(provider.awaitLine("READY ", START));
      try (TRADEContainer caller = TRADEContainer.builder().name("caller")
          .property("CONNECTCONTAINERS", address).property("FAILURETIMEOUT", "60000").build()) {
        killDuringCall(provider, caller);
      }
    }
  }

  @Test
  void killedProviderThatDialledIn() throws Exception {
    try (TRADEContainer caller = Hubs.hubBuilder("caller").property("FAILURETIMEOUT", "60000")
        .build();
        JvmProcess provider = ProviderMain.launch(List.of(), "CONTAINERNAME=victim",
            "CONNECTCONTAINERS=" + caller.getServerAddresses().get(0))) {
      provider.awaitLine("READY ", START);
      killDuringCall(provider, caller);
    }
  }

  private static void killDuringCall(JvmProcess provider, TRADEContainer caller) throws Exception {
    Await.until(START, () -> caller.getAvailableServices(PROVIDED).size() == ProviderMain.serviceCount(),
        "the provider's services");
    TRADEServiceInfo slow = caller.getAvailableService(new TRADEServiceConstraints().name("slow"));

    // Calls that would block for a minute (their deadline is CALLTIMEOUT, 30 s by default).
    List<CompletableFuture<Throwable>> outcomes = new ArrayList<>();
    AtomicLong lastFailureAt = new AtomicLong();
    for (int i = 0; i < CALLERS; i++) {
      CompletableFuture<Throwable> outcome = new CompletableFuture<>();
      outcomes.add(outcome);
      Thread t = new Thread(() -> {
        try {
          slow.call(long.class, 60_000L);
          outcome.complete(null);
        } catch (Throwable e) {
          lastFailureAt.accumulateAndGet(System.nanoTime(), Math::max);
          outcome.complete(e);
        }
      }, "slow-caller-" + i);
      t.setDaemon(true);
      t.start();
    }
    for (int i = 0; i < CALLERS; i++) {
      assertEquals("SLOW 60000", provider.awaitLine("SLOW ", START), "slow call " + i + " runs");
    }

    long killedAt = System.nanoTime();
    provider.kill();
    List<Throwable> errors = new ArrayList<>();
    for (CompletableFuture<Throwable> outcome : outcomes) {
      try {
        errors.add(outcome.get(10, TimeUnit.SECONDS));
      } catch (TimeoutException e) {
        throw new AssertionError("a caller still waits 10 s after the provider was killed", e);
      }
    }
    long toError = TimeUnit.NANOSECONDS.toMillis(lastFailureAt.get() - killedAt);
    Await.until(Duration.ofSeconds(10), () -> caller.getAvailableServices(PROVIDED).isEmpty(),
        "the killed provider's services to disappear");
    long toGone = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - killedAt);
    System.out.println("kill -9 -> last of " + CALLERS + " callers failed: " + toError
        + " ms; -> services gone: " + toGone + " ms");

    for (Throwable error : errors) {
      TRADEServiceUnavailableException unavailable =
          assertInstanceOf(TRADEServiceUnavailableException.class, error, "what a caller got");
      assertTrue(unavailable.getMessage().startsWith("Service not available any longer"),
          unavailable.getMessage());
    }
    assertTrue(toError <= LIMIT_MS, "callers failed up to " + toError + " ms after the kill");
    assertTrue(toGone <= LIMIT_MS, "services gone " + toGone + " ms after the kill");

    // Later calls through the old info fail the same way, at once.
    TRADEServiceUnavailableException again =
        assertThrows(TRADEServiceUnavailableException.class, () -> slow.call(long.class, 1L));
    assertTrue(again.getMessage().startsWith("Service not available any longer"), again.getMessage());
  }
}
