package dev.trade.internal.notify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Every timed type on a fake clock: when it fires, what it delivers, when it ends. */
class TimedNotificationsTest {
  private final Fixture f = new Fixture();
  private final Fixture.Battery battery = new Fixture.Battery();
  private final Fixture.Sink sink = new Fixture.Sink();

  @Test
  void afterFiresOnceAtItsDelayAndEnds() throws TRADEException {
    String id = f.request("after", 50L, null, f.service(sink, "tick"));
    f.advanceAndDeliver(49);
    assertEquals(List.of(), sink.got);
    f.advanceAndDeliver(1);
    assertEquals(List.of("tick"), sink.got);
    assertNull(f.engine.live(id), "ended after firing");
    assertEquals("it was due for the last time", f.engine.ended().get(0).get("endReason"));
    assertEquals(0, f.clock.pending());
  }

  @Test
  void afterTakesADurationAndAServiceWhoseResultItDelivers() throws TRADEException {
    f.request("after", new Object[] {Duration.ofMillis(20), 2, 3}, f.service(battery, "add"),
        f.service(sink, "value"));
    f.advanceAndDeliver(20);
    assertEquals(List.of("value 5"), sink.got);
  }

  @Test
  void atFiresAtItsInstant() throws TRADEException {
    Instant at = f.clock.instant().plusMillis(300);
    f.request("at", at, null, f.service(sink, "tick"));
    f.advanceAndDeliver(299);
    assertEquals(List.of(), sink.got);
    f.advanceAndDeliver(1);
    assertEquals(List.of("tick"), sink.got);
  }

  @Test
  void atAnInstantPassedFiresAtOnce() throws TRADEException {
    f.request("at", f.clock.instant().minusSeconds(5), null, f.service(sink, "tick"));
    f.advanceAndDeliver(0);
    assertEquals(List.of("tick"), sink.got);
  }

  @Test
  void onceCallsItsServiceWithoutWaitingAndDeliversTheResultOrTheFailure() throws TRADEException {
    f.request("once", new Object[] {4, 5}, f.service(battery, "add"), f.service(sink, "value"));
    f.request("once", null, f.service(battery, "levelOrFail"), f.service(sink, "valueOrFailure"));
    assertEquals(List.of(), sink.got, "nothing runs in the requester's call");
    f.advanceAndDeliver(0);
    assertEquals(2, sink.got.size());
    assertTrue(sink.got.contains("value 9"), sink.got.toString());
    assertTrue(sink.got.stream().anyMatch(s -> s.startsWith("failure ") && s.contains("sensor unplugged")),
        sink.got.toString());
  }

  @Test
  void everyFiresAtAFixedRateAndStreamsItsServicesResults() throws TRADEException {
    String id = f.request("every", 10L, f.service(battery, "level"), f.service(sink, "value"));
    f.advanceAndDeliver(9);
    assertEquals(List.of(), sink.got);
    for (int i = 0; i < 3; i++) {
      f.advanceAndDeliver(10);
    }
    assertEquals(List.of("value 100", "value 99", "value 98"), sink.got);
    Map<String, Object> shown = f.engine.list().get(0);
    assertEquals(id, shown.get("id"));
    assertEquals(3L, shown.get("timesFired"));
    // Due at 10, 20 and 30 ms after the request; the clock is at 39 ms.
    assertEquals(f.clock.instant().plusMillis(1), shown.get("nextTime"), "on the fixed-rate grid");
  }

  @Test
  void everySkipsAndCountsADeliveryThatWouldOverlapTheOneStillRunning() throws TRADEException {
    String id = f.request("every", Duration.ofMillis(10), null, f.service(sink, "tick"));
    f.clock.advanceMillis(10); // due: a delivery is handed over and has not run yet
    assertEquals(1, f.deliveries.queued());
    f.clock.advanceMillis(10); // due again while it runs: skipped, not queued beside it
    f.clock.advanceMillis(10);
    assertEquals(1, f.deliveries.queued());
    Live l = f.engine.live(id);
    assertEquals(2, l.skipped());
    f.deliveries.runAll();
    f.advanceAndDeliver(10);
    assertEquals(List.of("tick", "tick"), sink.got);
    assertEquals(2, l.skipped());
    assertEquals(2, l.fired());
  }

  @Test
  void dueTimesTheTimerMissedAreSkippedAndTheRateKept() throws TRADEException {
    Fixture.Sink s = sink;
    String id = f.request("every", 10L, null, f.service(s, "tick"));
    Live l = f.engine.live(id);
    long first = l.firstDue();
    // The timer thread ran 35 ms late: one delivery, the three due times it slept through skipped.
    Live.Step step = l.due(first + 35_000_000L);
    assertTrue(step.deliver());
    assertEquals(first, step.dueNanos(), "the delivery is the one due first");
    assertEquals(first + 40_000_000L, step.nextNanos(), "still on the fixed-rate grid");
    assertEquals(first + 39_000_000L, step.wakeNanos(), "the timer wakes a lead before it");
    assertEquals(3, l.skipped());
  }

  @Test
  void aFailingCallbackIsCountedAndTheNotificationGoesOn() throws TRADEException {
    String id = f.request("every", 5L, null, f.service(sink, "fails"));
    f.advanceAndDeliver(5);
    f.advanceAndDeliver(5);
    Live l = f.engine.live(id);
    assertEquals(List.of("fails", "fails"), sink.got);
    assertEquals(2, l.failures());
    assertFalse(l.ended());
    assertTrue(((String) f.engine.list().get(0).get("lastError")).contains("callback broke"),
        f.engine.list().toString());
  }

  @Test
  void ifCallsBackOnlyWhenItsConditionHoldsAtTheScheduledTime() throws TRADEException {
    ServiceDescriptor low = f.service(battery, "isLowBattery");
    String no = f.request("if", 100L, low, f.service(sink, "tick"));
    f.advanceAndDeliver(100);
    assertEquals(List.of(), sink.got);
    assertNull(f.engine.live(no), "an if is over once its time came");
    battery.low = true;
    f.request("if", f.clock.instant().plusMillis(100), low, f.service(sink, "tick"));
    f.advanceAndDeliver(100);
    assertEquals(List.of("tick"), sink.got);
  }

  @Test
  void whenPollsUntilItsConditionHoldsThenCallsBackOnceAndEnds() throws TRADEException {
    String id = f.request("when", 20L, f.service(battery, "isLowBattery"), f.service(sink, "tick"));
    f.advanceAndDeliver(20);
    f.advanceAndDeliver(20);
    assertEquals(2, battery.reads);
    assertEquals(List.of(), sink.got);
    battery.low = true;
    f.advanceAndDeliver(20);
    f.advanceAndDeliver(20);
    f.advanceAndDeliver(20);
    assertEquals(List.of("tick"), sink.got, "called back exactly once");
    assertEquals(3, battery.reads, "no poll after it fired");
    assertNull(f.engine.live(id));
    assertEquals("its condition became true", f.engine.ended().get(0).get("endReason"));
    assertEquals(0, f.clock.pending());
  }

  @Test
  void cancelStopsItAndLeavesNothingScheduled() throws TRADEException {
    String id = f.request("every", 10L, null, f.service(sink, "tick"));
    f.advanceAndDeliver(10);
    assertTrue(f.engine.cancel(id));
    assertFalse(f.engine.cancel(id), "cancelled once");
    f.advanceAndDeliver(100);
    assertEquals(List.of("tick"), sink.got);
    assertEquals(0, f.clock.pending());
    assertEquals("cancelled", f.engine.ended().get(0).get("endReason"));
  }

  /** The timer is the container's and outlives the engine: closing takes its tasks off it. */
  @Test
  void closingLeavesNothingOnTheContainersTimer() throws TRADEException {
    f.request("every", 10L, null, f.service(sink, "tick"));
    f.request("after", 1_000L, null, f.service(sink, "tick"));
    assertEquals(2, f.clock.pending());
    f.engine.close();
    assertEquals(0, f.clock.pending());
    f.advanceAndDeliver(2_000);
    assertEquals(List.of(), sink.got);
  }

  @Test
  void itEndsWhenItsCallbackOrItsConditionLeavesAndSaysWhy() throws TRADEException {
    Fixture.Sink other = new Fixture.Sink();
    String byCallback = f.request("every", 10L, null, f.service(other, "tick"));
    String byCondition = f.request("when", 10L, f.service(battery, "isLowBattery"),
        f.service(sink, "tick"));
    f.registry.deregister(other);
    f.registry.deregister(battery);
    f.advanceAndDeliver(50);
    assertNull(f.engine.live(byCallback));
    assertNull(f.engine.live(byCondition));
    List<Map<String, Object>> ended = f.engine.ended();
    assertEquals(2, ended.size());
    for (Map<String, Object> e : ended) {
      String reason = (String) e.get("endReason");
      if (e.get("id").equals(byCallback)) {
        assertEquals("its callback tick() @ one left", reason);
      } else {
        assertEquals("its service isLowBattery() @ one left", reason);
      }
    }
    assertEquals(List.of(), other.got);
    assertEquals(0, f.clock.pending());
  }
}
