package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/**
 * Closing linked containers ends their threads without uncaught exceptions: the link readers that
 * notice the closed sockets find the control thread stopped, and must not fail on it.
 */
class QuietCloseTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** A service, so that the link carries a table and a call before it closes. */
  public static final class Ping {
    @TRADEService
    public String ping() {
      return "pong";
    }
  }

  @Test
  void closingLinkedContainersThrowsNothingOnTheirThreads() throws Exception {
    List<String> uncaught = new CopyOnWriteArrayList<>();
    Thread.UncaughtExceptionHandler previous = Thread.getDefaultUncaughtExceptionHandler();
    Thread.setDefaultUncaughtExceptionHandler((t, e) -> uncaught.add(t.getName() + ": " + e));
    try {
      for (int i = 0; i < 10; i++) {
        String a = "quiet-a" + i;
        String b = "quiet-b" + i;
        try (TRADEContainer provider = Hubs.hubBuilder(a).build();
            TRADEContainer caller = Hubs.spokeBuilder(b, provider).build()) {
          provider.registerAllServices(new Ping());
          Await.until(WAIT, () -> !caller.getAvailableServices(new TRADEServiceConstraints().name("ping"))
              .isEmpty(), "the ping service");
          assertEquals("pong", caller.getAvailableService(new TRADEServiceConstraints().name("ping"))
              .call(String.class));
        }
        Await.until(WAIT, () -> Thread.getAllStackTraces().keySet().stream()
            .noneMatch(t -> t.getName().equals("trade-link-" + a) || t.getName().equals("trade-link-" + b)),
            "the link threads of " + a + " and " + b + " to end");
      }
    } finally {
      Thread.setDefaultUncaughtExceptionHandler(previous);
    }
    assertEquals(List.of(), uncaught);
  }
}
