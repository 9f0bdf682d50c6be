package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The paper's before/after calls across three processes: a hook from JVM B (the observer) on
 * {@code setLow(boolean)} of JVM C (the battery), called from this JVM (A); then B is killed, and
 * C's calls go on and drop B's hooks.
 */
class HooksAcrossJvmsTest {
  private static final Duration START = Duration.ofSeconds(30);
  private static final Duration WAIT = Duration.ofSeconds(20);

  @Test
  void hooksFromAnotherJvmOnAServiceInAThirdSurviveTheObserversDeath() throws Exception {
    try (TRADEContainer a = TRADEContainer.builder().name("caller")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0").build()) {
      String hub = "CONNECTCONTAINERS=" + a.getServerAddresses().get(0);
      try (JvmProcess c = JvmProcess.start(RobotPartMain.class, List.of(), "battery",
              "CONTAINERNAME=battery", hub);
          JvmProcess b = JvmProcess.start(HookMain.class, List.of(), "setLow",
              "CONTAINERNAME=observer", hub)) {
        c.awaitLine("READY ", START);
        b.awaitLine("HOOKED", START);
        TRADEServiceInfo setLow = service(a, "setLow");

        setLow.call(void.class, true);
        b.awaitLine("BEFORE [setLow, true]", WAIT);
        b.awaitLine("AFTER [setLow, true, null]", WAIT);
        List<Map<String, Object>> hooks = a.getHooks();
        assertEquals(List.of("before", "after"), hooks.stream().map(h -> h.get("kind")).toList());
        assertEquals(List.of("seenAfter(java.lang.Object[])@observer", "setLow(boolean)@battery",
            "observer", 1L, 0L), List.of(hooks.get(1).get("wrapper"), hooks.get(1).get("target"),
            hooks.get(1).get("requester"), hooks.get(1).get("calls"), hooks.get(1).get("failures")));

        b.kill();
        setLow.call(void.class, false); // whether B's death is known yet or not, the call succeeds
        Await.until(WAIT, () -> a.getHooks().isEmpty(), "the battery dropping the dead hooks");
        setLow.call(void.class, true);
        assertEquals(true, service(a, "isLowBattery").call(boolean.class));
      }
    }
  }

  private static TRADEServiceInfo service(TRADEContainer c, String name) throws TRADEException {
    return c.waitForService(new TRADEServiceConstraints().name(name), START);
  }
}
