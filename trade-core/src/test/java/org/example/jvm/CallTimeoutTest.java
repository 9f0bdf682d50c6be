package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADETimeoutException;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A per-call deadline ({@link TRADEServiceInfo#withTimeout}) on a call to a provider JVM: the call
 * fails with the timeout type after about that long, only that call fails, and the link carries
 * later calls (and drops the late reply) as before.
 */
class CallTimeoutTest {
  private static final Duration START = Duration.ofSeconds(30);

  @Test
  void perCallTimeoutFailsOnlyThatCall() throws Exception {
    try (JvmProcess provider = ProviderMain.launch(List.of(), "CONTAINERNAME=provider",
        "STARTACCEPTINGCONNECTIONS=true", "SERVERIPS=127.0.0.1@0")) {
      String address = ProviderMain.address(provider.awaitLine("READY ", START));
      try (TRADEContainer caller = TRADEContainer.builder().name("caller")
          .property("CONNECTCONTAINERS", address).build()) {
        TRADEServiceConstraints provided = new TRADEServiceConstraints().inGroups("provider");
        Await.until(START, () -> caller.getAvailableServices(provided).size()
            == ProviderMain.serviceCount(), "the provider's services");
        TRADEServiceInfo slow = caller.getAvailableService(new TRADEServiceConstraints().name("slow"));
        TRADEServiceInfo echo = caller.getAvailableService(new TRADEServiceConstraints().name("echo"));
        TRADEServiceInfo hurried = slow.withTimeout(Duration.ofMillis(200));
        assertEquals(slow, hurried);

        long start = System.nanoTime();
        TRADETimeoutException e =
            assertThrows(TRADETimeoutException.class, () -> hurried.call(long.class, 700L));
        long elapsed = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
        System.out.println("200 ms per-call timeout fired after " + elapsed + " ms");
        assertTrue(elapsed >= 150 && elapsed <= 2000, "timed out after " + elapsed + " ms");
        assertTrue(e.getMessage().contains("slow(long)"), e.getMessage());
        assertEquals("SLOW 700", provider.awaitLine("SLOW ", START), "the call reached the provider");

        // The link is fine: a quick call, and a slow one whose reply comes while the timed-out
        // call's late reply (700) arrives; each caller gets its own.
        assertEquals("after", echo.call(String.class, "after"));
        assertEquals(400L, slow.call(long.class, 400L));
        assertEquals(List.of(1, 2), echo.call(List.class, List.of(1, 2)));
      }
    }
  }
}
