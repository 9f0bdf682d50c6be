package dev.trade.internal.notify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The timer hands a timed delivery to its thread a lead before it is due, and that thread waits for
 * the due time (on the container's clock: here a fake one).
 */
class DeliveryLeadTest {
  private static final Duration DEADLINE = Duration.ofSeconds(30);
  private final Fixture f = new Fixture();
  private final Fixture.Sink sink = new Fixture.Sink();

  @Test
  void theLeadIsAtMostHalfAPeriodAndAtMostOneMillisecond() throws TRADEException {
    Live oneMs = f.engine.live(f.request("every", 1L, null, f.service(sink, "tick")));
    Live tenMs = f.engine.live(f.request("every", 10L, null, f.service(sink, "tick")));
    Live after = f.engine.live(f.request("after", 50L, null, f.service(sink, "tick")));
    assertEquals(500_000L, oneMs.firstDue() - oneMs.firstWake());
    assertEquals(1_000_000L, tenMs.firstDue() - tenMs.firstWake());
    assertEquals(1_000_000L, after.firstDue() - after.firstWake());
  }

  @Test
  void aDeliveryIsHandedOverALeadBeforeItsTimeAndWaitsForIt() throws Exception {
    f.request("every", 10L, null, f.service(sink, "tick"));
    f.clock.advanceMillis(8);
    assertEquals(0, f.deliveries.queued());
    f.clock.advanceMillis(1); // 1 ms before it is due
    assertEquals(1, f.deliveries.queued(), "handed over a lead before its time");
    Thread delivery = new Thread(f.deliveries::runAll, "delivery");
    delivery.start();
    Await.until(DEADLINE, () -> f.clock.sleepers() == 1, "the delivery waits for its time");
    assertEquals(List.of(), sink.got, "not before its time");
    f.clock.advanceMillis(1);
    delivery.join(DEADLINE.toMillis());
    assertEquals(List.of("tick"), sink.got);
  }

  @Test
  void aNotificationCancelledWhileItsDeliveryWaitsDeliversNothing() throws Exception {
    String id = f.request("every", 10L, null, f.service(sink, "tick"));
    f.clock.advanceMillis(9);
    Thread delivery = new Thread(f.deliveries::runAll, "delivery");
    delivery.start();
    Await.until(DEADLINE, () -> f.clock.sleepers() == 1, "the delivery waits for its time");
    assertTrue(f.engine.cancel(id));
    f.clock.advanceMillis(1);
    delivery.join(DEADLINE.toMillis());
    assertEquals(List.of(), sink.got);
    assertEquals(0, f.clock.pending());
  }

  /**
   * A delivery still running when the timer wakes a lead before the next due time may end before
   * that time: the timer decides again at the due time, and skips only if it still runs then.
   */
  @Test
  void aDeliveryStillRunningAtTheLeadIsDecidedAgainAtTheDueTime() throws TRADEException {
    String id = f.request("every", 10L, null, f.service(sink, "tick"));
    Live l = f.engine.live(id);
    f.clock.advanceMillis(19); // the first handed over (not run), the second's lead came
    assertEquals(1, f.deliveries.queued());
    f.deliveries.runAll(); // the first runs and ends before the second is due
    f.advanceAndDeliver(1);
    assertEquals(List.of("tick", "tick"), sink.got);
    assertEquals(0, l.skipped());
    f.clock.advanceMillis(9); // 29 ms: the third is handed over and does not run
    f.clock.advanceMillis(10); // the fourth's lead: the third still runs; decided at its time
    assertEquals(0, l.skipped());
    f.clock.advanceMillis(1); // its time: the third still runs, so the fourth is skipped
    assertEquals(1, l.skipped());
    assertEquals(1, f.deliveries.queued());
  }

  /**
   * A callback that blocks holds up neither other notifications nor the container's timer: the
   * timer only hands deliveries over and never waits for one.
   */
  @Test
  @Timeout(120)
  void aSlowCallbackHoldsUpNeitherOtherNotificationsNorTheTimer() throws Exception {
    ExecutorService pool = Executors.newCachedThreadPool();
    Fixture g = new Fixture(pool);
    Slow slow = new Slow();
    try {
      Live stuck = g.engine.live(g.request("every", 10L, null, g.service(slow, "block")));
      Live ticks = g.engine.live(g.request("every", 10L, null, g.service(sink, "tick")));
      AtomicBoolean otherWork = new AtomicBoolean();
      g.clock.timer().schedule(() -> otherWork.set(true), 35, TimeUnit.MILLISECONDS);
      for (int i = 1; i <= 4; i++) {
        g.clock.advanceMillis(10);
        long fired = i;
        Await.until(DEADLINE, () -> ticks.fired() == fired, "tick " + fired);
      }
      assertTrue(slow.entered.await(DEADLINE.toMillis(), TimeUnit.MILLISECONDS));
      assertTrue(otherWork.get(), "the container's other timed work ran");
      assertEquals(3, stuck.skipped(), "the blocked one's later due times skipped, not queued");
      assertEquals(0, ticks.skipped());
    } finally {
      slow.release.countDown();
      g.engine.close();
      pool.shutdownNow();
    }
  }

  /** A callback that blocks until released. */
  public static final class Slow {
    final CountDownLatch entered = new CountDownLatch(1);
    final CountDownLatch release = new CountDownLatch(1);

    @TRADEService
    public void block() throws InterruptedException {
      entered.countDown();
      release.await(2, TimeUnit.MINUTES);
    }
  }
}
