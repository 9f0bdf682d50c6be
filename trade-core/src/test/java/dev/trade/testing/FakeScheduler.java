package dev.trade.testing;

import dev.trade.internal.time.Scheduler;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.AbstractExecutorService;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Delayed;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * A container's scheduler whose clock moves only when the test says so: {@link #advance} runs
 * every task that comes due, in the order of its time (then of scheduling), in the test's thread,
 * with the clock set to that time while it runs. Periodic tasks come back as on a real timer (at a
 * fixed rate or after a fixed delay). The clock starts at an arbitrary {@link #nanoTime} whose
 * {@link #instant} is {@link #EPOCH} plus that many nanoseconds.
 *
 * <pre>{@code
 * FakeScheduler clock = new FakeScheduler();
 * Deadlines deadlines = new Deadlines(clock, pending);
 * clock.advance(Duration.ofMillis(10)); // runs the sweep due by then
 * }</pre>
 *
 * <p>Safe for concurrent use; tasks run only in the thread that calls {@link #advance}.
 */
public final class FakeScheduler implements Scheduler {
  /** The wall-clock time of {@code nanoTime() == 0}. */
  public static final Instant EPOCH = Instant.parse("2025-01-01T00:00:00Z");

  private final List<Task<?>> tasks = new ArrayList<>(); // Guarded by this.
  private final Timer timer = new Timer();
  private long now = 1_000_000_000L; // Guarded by this.
  private long seq; // Guarded by this.
  private boolean closed; // Guarded by this.
  private int sleepers; // Guarded by this.

  @Override
  public synchronized long nanoTime() {
    return now;
  }

  @Override
  public synchronized Instant instant() {
    return EPOCH.plusNanos(now);
  }

  @Override
  public ScheduledExecutorService timer() {
    return timer;
  }

  @Override
  public synchronized void close() {
    closed = true;
    tasks.clear();
    notifyAll();
  }

  /**
   * Waits, in the calling thread (never the one that calls {@link #advance}, or it waits for
   * ever), until {@link #advance} moves the clock to {@code atNanos}, or the scheduler is closed.
   */
  @Override
  public synchronized void sleepUntil(long atNanos) throws InterruptedException {
    sleepers++;
    try {
      while (now - atNanos < 0 && !closed) {
        wait();
      }
    } finally {
      sleepers--;
    }
  }

  /** How many threads wait in {@link #sleepUntil} for the clock to move. */
  public synchronized int sleepers() {
    return sleepers;
  }

  /** How many tasks wait (cancelled ones are gone at once). */
  public synchronized int pending() {
    return tasks.size();
  }

  /** Moves the clock forward by {@code millis}, running each task as its time comes. */
  public void advanceMillis(long millis) {
    advance(Duration.ofMillis(millis));
  }

  /** Moves the clock forward by {@code by}, running each task as its time comes. */
  public void advance(Duration by) {
    long until;
    synchronized (this) {
      until = now + by.toNanos();
    }
    while (true) {
      Task<?> next;
      synchronized (this) {
        next = tasks.stream().filter(t -> t.at - until <= 0)
            .min(Comparator.<Task<?>>comparingLong(t -> t.at - until).thenComparingLong(t -> t.seq))
            .orElse(null);
        if (next == null) {
          now = until;
          notifyAll();
          return;
        }
        tasks.remove(next);
        if (next.at - now > 0) {
          now = next.at;
          notifyAll();
        }
      }
      next.run();
    }
  }

  private synchronized <V> Task<V> add(Callable<V> body, long delayNanos, long period) {
    if (closed) {
      throw new RejectedExecutionException("the scheduler is closed");
    }
    Task<V> t = new Task<>(body, now + Math.max(0, delayNanos), seq++, period);
    tasks.add(t);
    return t;
  }

  /**
   * One scheduled task. {@code period} is 0 for a task that runs once, positive for a fixed rate,
   * negative for a fixed delay.
   */
  private final class Task<V> implements ScheduledFuture<V> {
    private final Callable<V> body;
    private final long seq;
    private final long period;
    private final CompletableFuture<V> result = new CompletableFuture<>();
    private long at; // Guarded by FakeScheduler.this.

    Task(Callable<V> body, long at, long seq, long period) {
      this.body = body;
      this.at = at;
      this.seq = seq;
      this.period = period;
    }

    void run() {
      if (result.isDone()) {
        return;
      }
      V value;
      try {
        value = body.call();
      } catch (Throwable e) {
        result.completeExceptionally(e); // as a real timer: a periodic task that throws stops
        return;
      }
      if (period == 0) {
        result.complete(value);
        return;
      }
      synchronized (FakeScheduler.this) {
        if (!result.isDone() && !closed) {
          at = period > 0 ? at + period : now - period;
          tasks.add(this);
        }
      }
    }

    @Override
    public long getDelay(TimeUnit unit) {
      synchronized (FakeScheduler.this) {
        return unit.convert(at - now, TimeUnit.NANOSECONDS);
      }
    }

    @Override
    public int compareTo(Delayed o) {
      return Long.compare(getDelay(TimeUnit.NANOSECONDS), o.getDelay(TimeUnit.NANOSECONDS));
    }

    @Override
    public boolean cancel(boolean mayInterruptIfRunning) {
      synchronized (FakeScheduler.this) {
        tasks.remove(this);
      }
      return result.cancel(false);
    }

    @Override
    public boolean isCancelled() {
      return result.isCancelled();
    }

    @Override
    public boolean isDone() {
      return result.isDone();
    }

    @Override
    public V get() throws InterruptedException, ExecutionException {
      return result.get();
    }

    @Override
    public V get(long timeout, TimeUnit unit)
        throws InterruptedException, ExecutionException, TimeoutException {
      return result.get(timeout, unit);
    }
  }

  /** The timer view: delays count on the fake clock; {@code execute} means "due now". */
  private final class Timer extends AbstractExecutorService implements ScheduledExecutorService {
    @Override
    public ScheduledFuture<?> schedule(Runnable command, long delay, TimeUnit unit) {
      return add(Executors.callable(command), unit.toNanos(delay), 0);
    }

    @Override
    public <V> ScheduledFuture<V> schedule(Callable<V> callable, long delay, TimeUnit unit) {
      return add(callable, unit.toNanos(delay), 0);
    }

    @Override
    public ScheduledFuture<?> scheduleAtFixedRate(Runnable command, long initialDelay,
        long period, TimeUnit unit) {
      return add(Executors.callable(command), unit.toNanos(initialDelay), positive(period, unit));
    }

    @Override
    public ScheduledFuture<?> scheduleWithFixedDelay(Runnable command, long initialDelay,
        long delay, TimeUnit unit) {
      return add(Executors.callable(command), unit.toNanos(initialDelay), -positive(delay, unit));
    }

    private long positive(long period, TimeUnit unit) {
      if (period <= 0) {
        throw new IllegalArgumentException("period <= 0: " + period);
      }
      return unit.toNanos(period);
    }

    @Override
    public void execute(Runnable command) {
      schedule(command, 0, TimeUnit.NANOSECONDS);
    }

    @Override
    public void shutdown() {
      close();
    }

    @Override
    public List<Runnable> shutdownNow() {
      close();
      return List.of();
    }

    @Override
    public boolean isShutdown() {
      synchronized (FakeScheduler.this) {
        return closed;
      }
    }

    @Override
    public boolean isTerminated() {
      return isShutdown();
    }

    @Override
    public boolean awaitTermination(long timeout, TimeUnit unit) {
      return isShutdown();
    }
  }
}
