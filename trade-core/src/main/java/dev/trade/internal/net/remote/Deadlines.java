package dev.trade.internal.net.remote;

import dev.trade.internal.time.Scheduler;
import java.util.Map;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Fails the remote calls whose deadline has passed. Their callers wait without a timeout: a timed
 * wait arms a kernel timer for every call, which cost about 5 % of the calls 64 callers make in a
 * second (docs/benchmarks-log.md). Instead a sweep on the container's timer, every {@link #TICK_MS}
 * while calls are pending, completes each overdue one with its timeout, so a call fails at most a
 * tick after its deadline. The sweep stops after a second without pending calls and starts again
 * with the next call.
 *
 * <p>{@link #watch} is safe for concurrent use; the sweep runs on the timer thread.
 */
final class Deadlines {
  static final long TICK_MS = 10;
  private static final long IDLE_NANOS = TimeUnit.SECONDS.toNanos(1);

  private final Scheduler scheduler;
  private final Map<Long, RemoteCalls.Pending> pending;
  private volatile ScheduledFuture<?> sweeping;
  /** Since when the sweep found nothing pending (nanoTime), or 0; timer thread only. */
  private long idleSince;

  Deadlines(Scheduler scheduler, Map<Long, RemoteCalls.Pending> pending) {
    this.scheduler = scheduler;
    this.pending = pending;
  }

  /** Whether a sweep is scheduled now (for tests). */
  boolean sweeping() {
    return sweeping != null;
  }

  /** After a call was added to the pending calls: makes sure a sweep runs. */
  void watch() {
    if (sweeping != null) {
      return; // the common case: one volatile read per call
    }
    synchronized (this) {
      if (sweeping == null) {
        try {
          sweeping = scheduler.timer().scheduleWithFixedDelay(() -> sweep(scheduler.nanoTime()),
              TICK_MS, TICK_MS, TimeUnit.MILLISECONDS);
        } catch (RejectedExecutionException closing) {
          // The container is closing, and fails every pending call itself.
        }
      }
    }
  }

  /** One sweep at {@code now} (the scheduler's clock); timer thread only. */
  private void sweep(long now) {
    if (pending.isEmpty()) {
      if (idleSince == 0) {
        idleSince = now;
      } else if (now - idleSince > IDLE_NANOS) {
        idleSince = 0;
        synchronized (this) {
          sweeping.cancel(false);
          sweeping = null;
        }
        // A call added since the look above saw the old sweep and started none.
        if (!pending.isEmpty()) {
          watch();
        }
      }
      return;
    }
    idleSince = 0;
    for (Map.Entry<Long, RemoteCalls.Pending> e : pending.entrySet()) {
      RemoteCalls.Pending p = e.getValue();
      if (now - p.deadline() >= 0 && pending.remove(e.getKey(), p)) {
        p.reply().completeExceptionally(p.timedOut());
      }
    }
  }
}
