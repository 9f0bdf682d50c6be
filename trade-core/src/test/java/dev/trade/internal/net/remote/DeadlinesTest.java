package dev.trade.internal.net.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADETimeoutException;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.time.Scheduler;
import dev.trade.testing.FakeScheduler;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The sweep that fails overdue calls: each fails with its timeout within a tick or so of its
 * deadline, and no sooner; calls not yet due stay pending; the sweep stops when nothing has been
 * pending for a while, and starts again with the next call.
 */
class DeadlinesTest {
  private static final ServiceDescriptor SERVICE = new ServiceDescriptor("c", "arm", "h", 1,
      "openGripper", List.of("speed"), List.of("int"), "boolean", Set.of(), List.of());

  private final Scheduler timer = Scheduler.system("test");
  private final Map<Long, RemoteCalls.Pending> pending = new ConcurrentHashMap<>();
  private final Deadlines deadlines = new Deadlines(timer, pending);

  @AfterEach
  void stop() {
    timer.close();
  }

  private RemoteCalls.Pending call(long id, Duration timeout) {
    return call(deadlines, pending, System.nanoTime(), id, timeout);
  }

  private static RemoteCalls.Pending call(Deadlines deadlines,
      Map<Long, RemoteCalls.Pending> pending, long now, long id, Duration timeout) {
    RemoteCalls.Pending p = new RemoteCalls.Pending(new CompletableFuture<>(), UUID.randomUUID(),
        UUID.randomUUID(), now + timeout.toNanos(), SERVICE, timeout.toNanos());
    pending.put(id, p);
    deadlines.watch();
    return p;
  }

  /**
   * On a fake clock: the sweep decides by the scheduler's time, so a call fails at the first tick
   * at or after its deadline, never before, whatever the machine's speed.
   */
  @Test
  void onAFakeClockACallFailsAtTheFirstTickAtItsDeadline() {
    FakeScheduler clock = new FakeScheduler();
    Map<Long, RemoteCalls.Pending> calls = new ConcurrentHashMap<>();
    Deadlines sweep = new Deadlines(clock, calls);
    RemoteCalls.Pending soon = call(sweep, calls, clock.nanoTime(), 1, Duration.ofMillis(100));
    RemoteCalls.Pending later = call(sweep, calls, clock.nanoTime(), 2, Duration.ofMillis(105));
    clock.advanceMillis(99);
    assertFalse(soon.reply().isDone(), "failed before its deadline");
    clock.advanceMillis(1);
    assertTrue(soon.reply().isCompletedExceptionally(), "not failed at the tick of its deadline");
    assertFalse(calls.containsKey(1L));
    assertFalse(later.reply().isDone(), "failed 5 ms before its deadline");
    clock.advanceMillis(9);
    assertFalse(later.reply().isDone(), "failed before the next tick");
    clock.advanceMillis(1);
    assertTrue(later.reply().isCompletedExceptionally(), "not failed at the first tick after");
  }

  /** On a fake clock: the sweep stops a second after the last pending call, not sooner. */
  @Test
  void onAFakeClockTheSweepStopsASecondAfterTheLastCall() {
    FakeScheduler clock = new FakeScheduler();
    Map<Long, RemoteCalls.Pending> calls = new ConcurrentHashMap<>();
    Deadlines sweep = new Deadlines(clock, calls);
    call(sweep, calls, clock.nanoTime(), 1, Duration.ofMillis(10));
    clock.advanceMillis(10); // the call fails at this tick; the next finds nothing pending
    clock.advanceMillis(1_000);
    assertTrue(sweep.sweeping(), "stopped within a second of idling");
    clock.advanceMillis(20);
    assertFalse(sweep.sweeping(), "still sweeping over a second after the last call");
    assertEquals(0, clock.pending(), "the sweep left a task on the timer");
    call(sweep, calls, clock.nanoTime(), 2, Duration.ofMillis(10));
    assertTrue(sweep.sweeping());
  }

  @Test
  void anOverdueCallFailsWithItsTimeoutAndOneNotDueStaysPending() throws Exception {
    long start = System.nanoTime();
    RemoteCalls.Pending soon = call(1, Duration.ofMillis(100));
    RemoteCalls.Pending later = call(2, Duration.ofMinutes(10));
    ExecutionException e = assertThrows(ExecutionException.class,
        () -> soon.reply().get(10, TimeUnit.SECONDS));
    long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
    assertTrue(waited >= 100, "failed after " + waited + " ms, before its deadline");
    assertTrue(e.getCause() instanceof TRADETimeoutException, e.toString());
    assertEquals("Service openGripper(int) of container arm did not answer within 100 ms",
        e.getCause().getMessage());
    assertFalse(pending.containsKey(1L), "an overdue call left pending");
    assertFalse(later.reply().isDone(), "a call failed before its deadline");
    assertTrue(pending.containsKey(2L));
  }

  @Test
  void theSweepStopsWhenNothingIsPendingAndStartsAgainWithTheNextCall() throws Exception {
    RemoteCalls.Pending first = call(1, Duration.ofMillis(10));
    assertThrows(ExecutionException.class, () -> first.reply().get(10, TimeUnit.SECONDS));
    Await.until(Duration.ofSeconds(10), () -> !deadlines.sweeping(), "the sweep to stop");
    RemoteCalls.Pending next = call(2, Duration.ofMillis(10));
    assertTrue(deadlines.sweeping());
    assertThrows(ExecutionException.class, () -> next.reply().get(10, TimeUnit.SECONDS));
  }
}
