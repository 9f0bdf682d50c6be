package dev.trade.internal.time;

import java.time.Instant;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * One container's clock and timer (see the package comment). Implementations are safe for
 * concurrent use.
 */
public interface Scheduler {
  /** Now, as {@link System#nanoTime}: compare readings by subtraction, never by value. */
  long nanoTime();

  /** The wall-clock time of the same moment (for notifications {@code at} an instant). */
  Instant instant();

  /**
   * The timer, whose delays count on this clock. Its tasks must be short; only {@link #close}
   * shuts it down, so the components handed it cancel their own tasks and never shut it.
   */
  ScheduledExecutorService timer();

  /**
   * Runs {@code task} once at {@code atNanos} ({@link #nanoTime} scale), or as soon as possible if
   * that has passed.
   *
   * @return what cancels it
   * @throws RejectedExecutionException once the scheduler is closed
   */
  default Runnable schedule(Runnable task, long atNanos) {
    ScheduledFuture<?> f = timer().schedule(task, atNanos - nanoTime(), TimeUnit.NANOSECONDS);
    return () -> f.cancel(false);
  }

  /**
   * Parks the calling thread until this clock reaches {@code atNanos} ({@link #nanoTime} scale);
   * returns at once if it has. For a task handed to another thread a little before its time, so
   * that it starts at its time with one wake-up rather than the timer's and then its thread's.
   *
   * @throws InterruptedException the thread was interrupted while it waited
   */
  default void sleepUntil(long atNanos) throws InterruptedException {
    for (long left = atNanos - nanoTime(); left > 0; left = atNanos - nanoTime()) {
      LockSupport.parkNanos(this, left);
      if (Thread.interrupted()) {
        throw new InterruptedException();
      }
    }
  }

  /** Stops the timer; tasks not run yet never run, and new ones are rejected. Idempotent. */
  void close();

  /**
   * The real clock, with one daemon timer thread named {@code trade-timer-NAME} that starts with
   * the first task (a container that schedules nothing starts none).
   */
  static Scheduler system(String name) {
    ScheduledThreadPoolExecutor timer = new ScheduledThreadPoolExecutor(1, r -> {
      Thread t = new Thread(r, "trade-timer-" + name);
      t.setDaemon(true);
      return t;
    });
    // Calls' deadlines, dials and notifications cancel most of what they schedule.
    timer.setRemoveOnCancelPolicy(true);
    return of(timer);
  }

  /**
   * The real clock with {@code timer}, which {@link #close} shuts down (for tests that watch or
   * hold back what is scheduled).
   */
  static Scheduler of(ScheduledExecutorService timer) {
    return new Scheduler() {
      @Override
      public long nanoTime() {
        return System.nanoTime();
      }

      @Override
      public Instant instant() {
        return Instant.now();
      }

      @Override
      public ScheduledExecutorService timer() {
        return timer;
      }

      @Override
      public void close() {
        timer.shutdownNow();
      }
    };
  }
}
