package org.example.hooks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Before and after hooks within one container, through the public API. */
class HooksTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final List<TRADEContainer> built = new ArrayList<>();

  @AfterEach
  void close() {
    built.forEach(TRADEContainer::close);
  }

  private TRADEContainer container(String name, String... settings) {
    TRADEContainer.Builder b = TRADEContainer.builder().name(name);
    for (int i = 0; i < settings.length; i += 2) {
      b.property(settings[i], settings[i + 1]);
    }
    TRADEContainer c = b.build();
    built.add(c);
    return c;
  }

  /** Registers a {@link Robot} (group robot) and a {@link Recorder} (group hooks) sharing events. */
  static Recorder robotAndRecorder(TRADEContainer c) throws TRADEException {
    Recorder r = new Recorder();
    c.registerAllServices(r, "hooks");
    c.registerAllServices(new Robot(r.events), "robot");
    return r;
  }

  static TRADEServiceInfo service(TRADEContainer c, String name) throws TRADEException {
    return c.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  @Test
  void beforeServiceAndAfterRunInOrderWithTheirArrays() throws TRADEException {
    TRADEContainer c = container("order");
    Recorder r = robotAndRecorder(c);
    TRADEServiceInfo open = service(c, "openGripper");
    c.beforeService(service(c, "before"), open);
    c.afterService(service(c, "after"), open);

    assertEquals(true, open.call(boolean.class, 3, "gently"));
    assertEquals(List.of("before [openGripper, 3, gently]", "S openGripper 3 gently",
        "after [openGripper, 3, gently, true]"), r.events);
  }

  @Test
  void voidGivesNullAndAFailureIsNullOrTheThrowable() throws TRADEException {
    TRADEContainer c = container("void");
    Recorder r = robotAndRecorder(c);
    c.afterService(service(c, "after"), service(c, "sayText"));
    c.afterService(service(c, "after"), service(c, "fail"));
    c.afterService(service(c, "afterWithFailure"), service(c, "fail"));
    c.afterService(service(c, "afterWithFailure"), service(c, "sayText"));

    service(c, "sayText").call(void.class, "okay");
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class,
        () -> service(c, "fail").call(int.class, 7));
    assertEquals("code 7", e.getCause().getMessage(), "the caller gets exactly the failure");
    assertEquals(List.of("S sayText okay", "after [sayText, okay, null]",
        "afterWithFailure [sayText, okay, null] returned",
        "S fail 7", "after [fail, 7, null]",
        "afterWithFailure [fail, 7, null] threw TRADEInvocationException caused by code 7"),
        r.events);
  }

  @Test
  void severalHooksRunInTheOrderTheyWereAddedAndAddingTwiceAddsOnce() throws TRADEException {
    TRADEContainer c = container("several");
    List<String> events = java.util.Collections.synchronizedList(new ArrayList<>());
    Recorder first = new Recorder(events);
    Recorder second = new Recorder(events) {
      @Override
      @TRADEService
      public void after(Object[] call) {
        events.add("second " + call[0]);
      }
    };
    c.registerAllServices(first, "one");
    c.registerAllServices(second, "two");
    c.registerAllServices(new Robot(events), "robot");
    TRADEServiceInfo say = service(c, "sayText");
    TRADEServiceInfo secondAfter = c.getAvailableService(
        new TRADEServiceConstraints().name("after").inGroups("two"));
    c.afterService(secondAfter, say);
    c.afterService(c.getAvailableService(new TRADEServiceConstraints().name("after")
        .inGroups("one")), say);
    c.afterService(secondAfter, say);

    say.call(void.class, "hi");
    assertEquals(List.of("S sayText hi", "second sayText", "after [sayText, hi, null]"), events);
    assertEquals(2, c.getHooks().size());
  }

  @Test
  void aHookThatMutatesItsArrayChangesNeitherTheArgumentsNorTheResult() throws TRADEException {
    TRADEContainer c = container("vandal");
    Recorder r = robotAndRecorder(c);
    TRADEServiceInfo open = service(c, "openGripper");
    c.beforeService(service(c, "vandal"), open);
    c.afterService(service(c, "vandal"), open);
    c.afterService(service(c, "after"), open);

    assertEquals(true, open.call(boolean.class, 5, "firmly"));
    assertEquals(List.of("vandal [openGripper, 5, firmly]", "S openGripper 5 firmly",
        "vandal [openGripper, 5, firmly, true]", "after [openGripper, 5, firmly, true]"), r.events);
  }

  @Test
  void strictModeGivesHooksCopiesOfTheArgumentObjects() throws TRADEException {
    TRADEContainer c = container("strict", "COPYDATAFORLOCALINVOKES", "true");
    Recorder r = robotAndRecorder(c);
    TRADEServiceInfo echo = service(c, "echo");
    c.beforeService(service(c, "mutateObjects"), echo);

    List<String> items = new ArrayList<>(List.of("a", "b"));
    assertEquals(List.of("a", "b"), echo.call(List.class, items));
    assertEquals(List.of("S echo [a, b]"), r.events);
    assertEquals(List.of("a", "b"), items);
  }

  @Test
  void aThrowingHookIsCountedAndNeverFailsTheCall() throws TRADEException {
    TRADEContainer c = container("throwing");
    Recorder r = robotAndRecorder(c);
    TRADEServiceInfo open = service(c, "openGripper");
    c.beforeService(service(c, "fails"), open);
    c.afterService(service(c, "fails"), open);

    assertEquals(false, open.call(boolean.class, 1, "softly"));
    assertEquals(true, open.call(boolean.class, 4, "hard"));
    assertEquals(List.of("fails", "S openGripper 1 softly", "fails", "fails",
        "S openGripper 4 hard", "fails"), r.events);
    for (Map<String, Object> h : c.getHooks()) {
      assertEquals(2L, h.get("calls"), h.toString());
      assertEquals(2L, h.get("failures"), h.toString());
    }
  }

  /**
   * A local wrapper that hangs delays its call by the hook timeout at most: it runs on a thread
   * of its own, which it keeps until it ends, and fails its hook. The call returns while both
   * wrappers still hang; released, they end, and nothing is left waiting.
   */
  @Test
  void aHangingLocalHookDelaysTheCallByTheHookTimeoutAtMost() throws Exception {
    TRADEContainer c = container("hanging", "HOOKTIMEOUT", "200");
    CountDownLatch release = new CountDownLatch(1);
    CountDownLatch ended = new CountDownLatch(2);
    Object hangs = new Object() {
      @TRADEService
      public void hang(Object[] call) throws InterruptedException {
        release.await();
        ended.countDown();
      }
    };
    c.registerAllServices(hangs, "hooks");
    c.registerAllServices(new Robot(new ArrayList<>()), "robot");
    TRADEServiceInfo open = service(c, "openGripper");
    c.beforeService(service(c, "hang"), open);
    c.afterService(service(c, "hang"), open);
    try {
      CompletableFuture<Boolean> call = CompletableFuture.supplyAsync(() -> {
        try {
          return open.call(boolean.class, 3, "anyway");
        } catch (TRADEException e) {
          throw new CompletionException(e);
        }
      });
      assertEquals(true, call.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the call's result");
      assertEquals(2, ended.getCount(), "the call returned after its wrappers");
      assertEquals(List.of(1L, 1L), c.getHooks().stream().map(h -> h.get("failures")).toList());
    } finally {
      release.countDown();
    }
    assertTrue(ended.await(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the wrappers ended");
    Await.until(WAIT, () -> c.getHooks().stream().allMatch(h -> h.get("calls").equals(1L)),
        "the wrappers' calls counted as they ended");
  }

  @Test
  void anAsynchronousAfterHookDoesNotDelayTheCaller() throws Exception {
    TRADEContainer c = container("async");
    CountDownLatch release = new CountDownLatch(1);
    CountDownLatch ran = new CountDownLatch(1);
    Object slow = new Object() {
      @TRADEService
      public void slowAfter(Object[] call) throws InterruptedException {
        release.await();
        ran.countDown();
      }
    };
    c.registerAllServices(slow, "hooks");
    c.registerAllServices(new Robot(new ArrayList<>()), "robot");
    c.afterService(service(c, "slowAfter"), service(c, "openGripper"), true);

    assertEquals(true, c.getAvailableService(new TRADEServiceConstraints().name("openGripper"))
        .call(boolean.class, 9, "now"), "returned while the hook waits");
    assertEquals(1, ran.getCount());
    release.countDown();
    assertTrue(ran.await(WAIT.toMillis(), TimeUnit.MILLISECONDS));
    assertEquals("after-async", c.getHooks().get(0).get("kind"));
  }

  /** A wrapper that calls its own target: the hook is not run again inside its own call. */
  public static class SelfCaller {
    final List<String> events = java.util.Collections.synchronizedList(new ArrayList<>());
    TRADEServiceInfo target;

    @TRADEService
    public void observe(Object[] call) throws TRADEException {
      events.add("observe " + call[0]);
      if (target != null) {
        target.call(void.class, "from the hook");
      }
    }

    @TRADEService
    public void ping(String s) {
      events.add("ping " + s);
    }

    @TRADEService
    public void onPing(Object[] call) throws TRADEException {
      events.add("onPing " + call[0]);
    }
  }

  @Test
  void cyclesAreCut() throws TRADEException {
    TRADEContainer c = container("cycles");
    SelfCaller s = new SelfCaller();
    c.registerAllServices(s, "x");
    TRADEServiceInfo observe = service(c, "observe");
    TRADEServiceInfo ping = service(c, "ping");
    TRADEServiceInfo onPing = service(c, "onPing");

    // A hook on itself.
    c.afterService(observe, observe);
    observe.call(void.class, (Object) new Object[] {"direct"});
    assertEquals(List.of("observe direct", "observe observe"), s.events);

    // Its wrapper calls its own target: the inner call runs without that hook.
    s.events.clear();
    assertTrue(c.removeAfterService(observe, observe));
    s.target = ping;
    c.afterService(observe, ping);
    ping.call(void.class, "outer");
    assertEquals(List.of("ping outer", "observe ping", "ping from the hook"), s.events);

    // Two hooks on each other: onPing after observe, observe after onPing.
    s.events.clear();
    s.target = null;
    c.afterService(onPing, observe);
    c.afterService(observe, onPing);
    ping.call(void.class, "two");
    assertEquals(List.of("ping two", "observe ping", "onPing observe"), s.events,
        "observe runs inside its own path, so not after onPing there");
    s.events.clear();
    onPing.call(void.class, (Object) new Object[] {"direct"});
    assertEquals(List.of("onPing direct", "observe onPing", "onPing observe"), s.events,
        "each hook runs once on a path: the direct call is not a hook's");
  }

  @Test
  void removalStopsTheHookAndSaysWhetherThereWasOne() throws TRADEException {
    TRADEContainer c = container("removal");
    Recorder r = robotAndRecorder(c);
    TRADEServiceInfo say = service(c, "sayText");
    c.beforeService(service(c, "before"), say);
    c.afterService(service(c, "after"), say);
    assertTrue(c.removeBeforeService(service(c, "before"), say));
    assertFalse(c.removeBeforeService(service(c, "before"), say));
    say.call(void.class, "once");
    assertTrue(c.removeAfterService(service(c, "after"), say));
    say.call(void.class, "twice");
    assertEquals(List.of("S sayText once", "after [sayText, once, null]", "S sayText twice"),
        r.events);
    assertEquals(List.of(), c.getHooks());
  }

  @Test
  void aHookWhoseWrapperLeftIsRemoved() throws TRADEException {
    TRADEContainer c = container("left");
    Recorder r = robotAndRecorder(c);
    c.afterService(service(c, "after"), service(c, "sayText"));
    assertEquals(1, c.getHooks().size());
    c.deregister(r);
    assertEquals(List.of(), c.getHooks());
    service(c, "sayText").call(void.class, "alone");
    assertEquals(List.of("S sayText alone"), r.events);
  }

  @Test
  void badRequestsAreRefusedWithTheReason() throws TRADEException {
    TRADEContainer c = container("bad");
    Recorder r = robotAndRecorder(c);
    TRADEBadArgumentsException shape = assertThrows(TRADEBadArgumentsException.class,
        () -> c.afterService(service(c, "notAWrapper"), service(c, "sayText")));
    assertEquals("Wrapper notAWrapper(java.lang.String)@bad cannot take a hook's call: it must take"
        + " one Object[] (or Object[] and Throwable, to learn that the target threw; or those and a"
        + " Map, for the call's details)", shape.getMessage());
    assertThrows(TRADEBadArgumentsException.class,
        () -> c.beforeService(service(c, "afterWithFailure"), service(c, "sayText")));
    TRADEServiceInfo listHooks = c.getAvailableService(
        new TRADEServiceConstraints().name("listHooks").inGroups("trade.system"));
    TRADEBadArgumentsException system = assertThrows(TRADEBadArgumentsException.class,
        () -> c.afterService(service(c, "after"), listHooks));
    assertTrue(system.getMessage().endsWith("set HOOKSYSTEMSERVICES=true in its configuration to"
        + " allow it"), system.getMessage());
    assertEquals(List.of(), c.getHooks());
  }

  @Test
  void systemServicesCanBeHookedWhereAllowed() throws TRADEException {
    TRADEContainer c = container("allowed", "HOOKSYSTEMSERVICES", "true");
    Recorder r = new Recorder();
    c.registerAllServices(r, "hooks");
    TRADEServiceInfo listHooks = c.getAvailableService(
        new TRADEServiceConstraints().name("listHooks").inGroups("trade.system"));
    c.afterService(service(c, "after"), listHooks);
    assertEquals(1, c.getHooks().size());
    assertEquals(List.of("after [listHooks, " + List.of(c.getHooks().get(0)).toString()
        .replace("calls=1", "calls=0") + "]"), List.of(r.events.get(0)));
  }

  @Test
  void thePapersStringForm() throws TRADEException {
    TRADEContainer c = container("paper");
    Recorder r = robotAndRecorder(c);
    c.afterService("after", new String[] {Object[].class.getName()},
        new TRADEServiceConstraints(), "openGripper", new String[] {"int", "java.lang.String"},
        null);
    c.beforeService("before", new String[] {"java.lang.Object[]"}, null, "sayText", null,
        new TRADEServiceConstraints().inGroups("robot"));
    service(c, "openGripper").call(boolean.class, 1, "x");
    service(c, "sayText").call(void.class, "y");
    assertEquals(List.of("S openGripper 1 x", "after [openGripper, 1, x, false]",
        "before [sayText, y]", "S sayText y"), r.events);
    assertThrows(TRADEBadArgumentsException.class, () -> c.afterService("after",
        new String[] {"com.example.NoSuchClass"}, null, "sayText", null, null));
  }

  /** DIARC's TradeServiceTracker: an after hook on every service, registered in its own group. */
  public static class Tracker {
    final List<String> seen = java.util.Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void trackService(Object[] call) {
      seen.add(String.valueOf(call[0]));
    }
  }

  @Test
  void aSetCoversEveryMatchingServiceIncludingLaterOnesButNotItsWrapperOrSystemServices()
      throws TRADEException {
    TRADEContainer c = container("tracker");
    Tracker t = new Tracker();
    c.registerAllServices(t, "MonitoringGroup");
    Robot robot = new Robot(new ArrayList<>());
    c.registerAllServices(robot, "robot");
    TRADEServiceInfo track = service(c, "trackService");
    assertEquals(4, c.afterServices(track, new TRADEServiceConstraints()), "the robot's four");

    Object later = new Object() {
      @TRADEService
      public String late() {
        return "late";
      }
    };
    c.registerAllServices(later, "later");
    Await.until(WAIT, () -> c.getHooks().size() == 5, "the hook on late()");
    service(c, "late").call(String.class);
    service(c, "sayText").call(void.class, "hello");
    track.call(void.class, (Object) new Object[] {"direct"});
    c.getAvailableService(new TRADEServiceConstraints().name("listHooks")
        .inGroups("trade.system")).call(List.class);
    assertEquals(List.of("late", "sayText", "direct"), t.seen);

    assertTrue(c.removeAfterServices(track, new TRADEServiceConstraints()));
    assertEquals(List.of(), c.getHooks());
    service(c, "sayText").call(void.class, "quiet");
    assertEquals(3, t.seen.size());
  }
}
