package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/**
 * The first call over a new link is answered. The caller may call as soon as it sees the
 * provider's services, before the provider has applied the caller's link state and so before it
 * has a route back; the reply then takes the link the call came in on.
 */
class FirstCallTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** A provided service. */
  public static final class Ping {
    @TRADEService
    public String ping(int n) {
      return "pong " + n;
    }
  }

  @Test
  void firstCallOnEachNewLinkIsAnswered() throws Exception {
    for (int i = 0; i < 20; i++) {
      try (TRADEContainer provider = Hubs.hubBuilder("first-provider-" + i).build()) {
        provider.registerAllServices(new Ping());
        // A lost reply shows as a timeout after 5 s rather than after the default 30 s.
        try (TRADEContainer caller = TRADEContainer.builder().name("first-caller-" + i)
            .property("CALLTIMEOUT", "5000")
            .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build()) {
          TRADEServiceConstraints ping = new TRADEServiceConstraints().name("ping");
          Await.until(WAIT, () -> !caller.getAvailableServices(ping).isEmpty(), "the ping service");
          assertEquals("pong " + i, caller.getAvailableService(ping).call(String.class, i),
              "first call on link " + i);
        }
      }
    }
  }
}
