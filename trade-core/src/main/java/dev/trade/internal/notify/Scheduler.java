package dev.trade.internal.notify;

import java.time.Instant;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * The time and timer notifications run on: the seam through which tests drive them with a fake
 * clock. Implementations are safe for concurrent use.
 */
interface Scheduler {
  /** The time, as {@link System#nanoTime}. */
  long nanoTime();

  /** The wall-clock time of the same moment (for {@code at} and {@code if} with an instant). */
  Instant instant();

  /**
   * Runs {@code task} once at {@code atNanos} ({@link #nanoTime} scale), or as soon as possible if
   * that has passed.
   *
   * @return what cancels it
   * @throws RejectedExecutionException once the scheduler is closed
   */
  Runnable schedule(Runnable task, long atNanos);

  /** Stops; tasks not run yet never run. */
  void close();

  /**
   * The real clock, with one timer thread started at the first {@link #schedule} (a container that
   * requests no timed notification starts none).
   */
  static Scheduler system(String name) {
    return new Scheduler() {
      private ScheduledThreadPoolExecutor timer; // Guarded by this.
      private boolean closed; // Guarded by this.

      @Override
      public long nanoTime() {
        return System.nanoTime();
      }

      @Override
      public Instant instant() {
        return Instant.now();
      }

      @Override
      public Runnable schedule(Runnable task, long atNanos) {
        ScheduledFuture<?> f = timer().schedule(task, atNanos - System.nanoTime(),
            TimeUnit.NANOSECONDS);
        return () -> f.cancel(false);
      }

      private synchronized ScheduledThreadPoolExecutor timer() {
        if (closed) {
          throw new RejectedExecutionException("notifications of " + name + " are closed");
        }
        if (timer == null) {
          timer = new ScheduledThreadPoolExecutor(1, r -> {
            Thread t = new Thread(r, "trade-notify-timer-" + name);
            t.setDaemon(true);
            return t;
          });
          timer.setRemoveOnCancelPolicy(true);
        }
        return timer;
      }

      @Override
      public synchronized void close() {
        closed = true;
        if (timer != null) {
          timer.shutdownNow();
        }
      }
    };
  }
}
