package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The TRADE paper's example across three processes: this JVM (A, the planner's) asks for
 * {@code dock()} (in JVM C) when {@code isLowBattery()} (in JVM B) becomes true. The notification
 * runs in B, where polling is a local call; the battery drops and C docks exactly once. A second
 * request is cancelled by its id from C; killing C ends a third, and B says why.
 */
class PaperNotificationTest {
  private static final Duration START = Duration.ofSeconds(30);
  private static final Duration WAIT = Duration.ofSeconds(20);
  private static final TRADEServiceConstraints SYSTEM = new TRADEServiceConstraints().inGroups("trade.system");

  @Test
  void whenLowBatteryDockAcrossThreeJvms() throws Exception {
    try (TRADEContainer a = Hubs.hubBuilder("planner").build()) {
      String hub = "CONNECTCONTAINERS=" + a.getServerAddresses().get(0);
      try (JvmProcess b = JvmProcess.start(RobotPartMain.class, List.of(), "battery",
              "CONTAINERNAME=battery", hub);
          JvmProcess c = JvmProcess.start(RobotPartMain.class, List.of(), "dock",
              "CONTAINERNAME=dock", hub)) {
        String bId = b.awaitLine("READY ", START).substring("READY ".length()).trim();
        c.awaitLine("READY ", START);
        TRADEServiceInfo isLow = service(a, "isLowBattery");
        TRADEServiceInfo dock = service(a, "dock");

        String first = a.requestNotification("when", 5L, List.of(isLow), dock);
        assertTrue(first.startsWith(bId + ":"), "runs in the battery's container: " + first);
        service(a, "setLow").call(void.class, true);
        c.awaitLine("DOCKED 1", WAIT);
        Await.until(WAIT, () -> ended(a, "battery").stream().anyMatch(e -> e.get("id").equals(first)),
            "the first ended");
        assertEquals(1, service(a, "dockCount").call(int.class), "docked exactly once");

        String second = a.requestNotification("when", 5L, List.of(service(a, "isOverheated")), dock);
        assertEquals(1, live(a, "battery").size());
        // C learns of the battery's container through the hub: on a busy machine its table may
        // reach C after the request was made, and until then C cannot reach its system services.
        TRADEServiceInfo cancelFromC = service(a, "cancelNotification");
        Await.until(WAIT, () -> {
          try {
            return cancelFromC.call(boolean.class, second);
          } catch (TRADEInvocationException e) {
            if (e.getCause() instanceof TRADEServiceUnavailableException) {
              return false; // not known in C yet
            }
            throw new AssertionError(e);
          } catch (TRADEException e) {
            throw new AssertionError(e);
          }
        }, "cancelled from C");
        assertEquals(List.of(), live(a, "battery"));
        assertEquals("cancelled", endReason(a, second));

        String third = a.requestNotification("when", 5L, List.of(service(a, "isOverheated")), dock);
        c.kill();
        Await.until(WAIT, () -> endReason(a, third) != null, "the third ended");
        assertEquals("its callback dock() @ dock left", endReason(a, third));
        assertEquals(List.of(), live(a, "battery"));
      }
    }
  }

  private static TRADEServiceInfo service(TRADEContainer c, String name) {
    TRADEServiceConstraints named = new TRADEServiceConstraints().name(name).inGroups("robot");
    Await.until(START, () -> !c.getAvailableServices(named).isEmpty(), name);
    return c.getAvailableServices(named).iterator().next();
  }

  private static TRADEServiceInfo system(TRADEContainer c, String name, String of) {
    Await.until(START, () -> c.getAvailableServices(SYSTEM).stream()
        .anyMatch(s -> s.serviceName.equals(name) && s.getContainerName().equals(of)), name + " of " + of);
    return c.getAvailableServices(SYSTEM).stream()
        .filter(s -> s.serviceName.equals(name) && s.getContainerName().equals(of)).findFirst().get();
  }

  @SuppressWarnings("unchecked")
  private static List<Map<String, Object>> live(TRADEContainer c, String of) throws TRADEException {
    return system(c, "listNotifications", of).call(List.class);
  }

  @SuppressWarnings("unchecked")
  private static List<Map<String, Object>> ended(TRADEContainer c, String of) {
    try {
      return system(c, "endedNotifications", of).call(List.class);
    } catch (TRADEException e) {
      throw new IllegalStateException(e);
    }
  }

  private static String endReason(TRADEContainer c, String id) {
    return ended(c, "battery").stream().filter(e -> e.get("id").equals(id))
        .map(e -> (String) e.get("endReason")).findFirst().orElse(null);
  }
}
