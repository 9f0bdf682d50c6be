package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
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
          TRADEContainer b = TRADEContainer.builder().name("B")
              .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0")
              .property("CONNECTCONTAINERS", a.getServerAddresses().get(0)).build();
          TRADEContainer c = TRADEContainer.builder().name("C")
              .property("CONNECTCONTAINERS", b.getServerAddresses().get(0)).build()) {
        a.registerAllServices(new Named("A"), "gA");
        TRADEServiceConstraints k = new TRADEServiceConstraints().inGroups("gA");
        Await.until(Duration.ofSeconds(5), () -> !c.getAvailableServices(k).isEmpty(), "gA on C");
        assertEquals("A answers C", c.getAvailableService(k).call(String.class, "C"), "round " + i);
      }
    }
  }

  private static TRADEContainer listening(String name) {
    return TRADEContainer.builder().name(name).property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0").build();
  }
}
