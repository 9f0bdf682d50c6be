package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/**
 * A chain whose links come up in any order routes as soon as a service is visible: link states
 * that arrive before the states connecting their owner must not be lost (found by this test).
 */
class ChainFormationTest {
  @Test
  void aServiceVisibleAcrossAFreshChainIsCallableAtOnce() throws TRADEException {
    for (int i = 0; i < 30; i++) {
      try (TRADEContainer a = listening("A");
          TRADEContainer b = Hubs.hubBuilder("B")
              .property("CONNECTCONTAINERS", a.getServerAddresses().get(0)).build();
          TRADEContainer c = Hubs.spokeBuilder("C", b).build()) {
        a.registerAllServices(new Named("A"), "gA");
        TRADEServiceConstraints k = new TRADEServiceConstraints().inGroups("gA");
        Await.until(Duration.ofSeconds(5), () -> !c.getAvailableServices(k).isEmpty(), "gA on C");
        assertEquals("A answers C", c.getAvailableService(k).call(String.class, "C"), "round " + i);
      }
    }
  }

  private static TRADEContainer listening(String name) {
    return Hubs.hubBuilder(name).build();
  }
}
