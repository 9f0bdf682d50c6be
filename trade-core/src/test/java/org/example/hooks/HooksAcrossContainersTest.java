package org.example.hooks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Hooks between containers linked over loopback: installed at the provider, they see local,
 * remote, forwarded and notification calls; the path in the call context cuts cycles across
 * containers; a hanging remote hook delays a call by the hook timeout at most.
 */
class HooksAcrossContainersTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  @RegisterExtension final Hubs net = new Hubs();

  private static TRADEServiceInfo find(TRADEContainer c, String name, String group) {
    return find(c, new TRADEServiceConstraints().name(name).inGroups(group));
  }

  /** The preferred service matching {@code wanted}, once {@code c} knows one. */
  static TRADEServiceInfo find(TRADEContainer c, TRADEServiceConstraints wanted) {
    Await.until(WAIT, () -> !c.getAvailableServices(wanted).isEmpty(), wanted.toString());
    return c.getAvailableServices(wanted).iterator().next();
  }

  @Test
  void aHookSeesLocalRemoteForwardedAndNotificationCalls() throws TRADEException {
    TRADEContainer hub = net.hub("observer");
    TRADEContainer provider = net.spoke("provider", hub);
    TRADEContainer caller = net.spoke("caller", hub);
    Recorder r = new Recorder();
    hub.registerAllServices(r, "hooks");
    provider.registerAllServices(new Robot(r.events), "robot");
    hub.afterService(find(hub, "after", "hooks"), find(hub, "sayText", "robot"));

    find(provider, "sayText", "robot").call(void.class, "local");
    find(hub, "sayText", "robot").call(void.class, "remote");
    find(caller, "sayText", "robot").call(void.class, "forwarded");
    caller.requestNotification("once", "notified", List.of(find(caller, "sayText", "robot")),
        find(caller, "before", "hooks"));
    Await.until(WAIT, () -> r.events.size() == 9, "the notification's call, hook and callback");
    assertEquals(List.of("S sayText local", "after [sayText, local, null]",
        "S sayText remote", "after [sayText, remote, null]",
        "S sayText forwarded", "after [sayText, forwarded, null]"), r.events.subList(0, 6));
    assertEquals(List.of("S sayText notified", "after [sayText, notified, null]"),
        r.events.subList(6, 8));
  }

  /** Two wrappers in two containers, each on the other; and one that calls its target again. */
  public static class Echo {
    final List<String> events;
    volatile TRADEServiceInfo again;

    Echo(List<String> events) {
      this.events = events;
    }

    @TRADEService
    public void echo(Object[] call) throws TRADEException {
      events.add("echo " + call[0] + (call.length > 1 && call[1] instanceof Object[] a
          ? " of " + a[0] : ""));
      if (again != null) {
        again.call(void.class, "again");
      }
    }
  }

  @Test
  void theCallContextCutsCyclesAcrossContainers() throws TRADEException {
    TRADEContainer one = net.hub("one");
    TRADEContainer two = net.spoke("two", one);
    List<String> events = Collections.synchronizedList(new ArrayList<>());
    Echo e1 = new Echo(events);
    Echo e2 = new Echo(events);
    one.registerAllServices(e1, "one");
    two.registerAllServices(e2, "two");
    two.registerAllServices(new Robot(events), "robot");
    TRADEServiceInfo echo1 = find(two, "echo", "one");
    TRADEServiceInfo echo2 = find(two, "echo", "two");
    TRADEServiceInfo say = find(one, "sayText", "robot");

    // The wrapper (in one) calls its target (in two) again: not hooked inside its own call.
    e1.again = say;
    one.afterService(find(one, "echo", "one"), say);
    say.call(void.class, "first");
    assertEquals(List.of("S sayText first", "echo sayText", "S sayText again"), events);
    assertTrue(one.removeAfterService(find(one, "echo", "one"), say));

    // Two hooks on each other, across the link.
    events.clear();
    e1.again = null;
    two.afterService(echo1, echo2);
    one.afterService(echo2, echo1);
    echo1.call(void.class, (Object) new Object[] {"direct"});
    assertEquals(List.of("echo direct", "echo echo of direct", "echo echo of echo"), events);
  }

  @Test
  void aHangingRemoteHookDelaysTheCallByTheHookTimeoutAtMost() throws TRADEException {
    TRADEContainer observer = net.hub("observer");
    TRADEContainer provider = net.keep(Hubs.spokeBuilder("provider", observer)
        .property("HOOKTIMEOUT", "200").build());
    CountDownLatch never = new CountDownLatch(1);
    Object hangs = new Object() {
      @TRADEService
      public void hang(Object[] call) throws InterruptedException {
        never.await();
      }
    };
    try {
      observer.registerAllServices(hangs, "hooks");
      provider.registerAllServices(new Robot(new ArrayList<>()), "robot");
      TRADEServiceInfo open = find(observer, "openGripper", "robot");
      observer.beforeService(find(observer, "hang", "hooks"), open);
      observer.afterService(find(observer, "hang", "hooks"), open);

      assertEquals(true, open.call(boolean.class, 3, "anyway"));
      List<Map<String, Object>> hooks = observer.getHooks();
      assertEquals(List.of(1L, 1L), hooks.stream().map(h -> h.get("failures")).toList());
    } finally {
      never.countDown();
    }
  }

  @Test
  void aSetFromAnotherContainerCoversServicesThatJoinLater() throws TRADEException {
    TRADEContainer monitor = net.hub("monitor");
    TRADEContainer robot = net.spoke("robot", monitor);
    List<String> seen = Collections.synchronizedList(new ArrayList<>());
    Object tracker = new Object() {
      @TRADEService
      public void trackService(Object[] call) {
        seen.add(call[0] + "@" + call[call.length - 1]);
      }
    };
    monitor.registerAllServices(tracker, "MonitoringGroup");
    robot.registerAllServices(new Robot(new ArrayList<>()), "robot");
    TRADEServiceInfo track = find(monitor, "trackService", "MonitoringGroup");
    find(monitor, "echo", "robot");
    assertEquals(4, monitor.afterServices(track, new TRADEServiceConstraints().inGroups("robot"),
        true));

    Object late = new Object() {
      @TRADEService
      public String late() {
        return "late";
      }
    };
    robot.registerAllServices(late, "robot");
    Await.until(WAIT, () -> monitor.getHooks().size() == 5, "the hook on late()");
    find(robot, "late", "robot").call(String.class);
    find(monitor, "openGripper", "robot").call(boolean.class, 3, "x");
    Await.until(WAIT, () -> seen.size() == 2, "both asynchronous hooks");
    // Asynchronous hooks: each call's record comes in the order its delivery ran, not the calls'.
    assertEquals(java.util.Set.of("late@late", "openGripper@true"), java.util.Set.copyOf(seen));
  }
}
