package dev.trade.internal.hooks;

import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Runs the synchronous hooks' wrappers that are services of this container, each on a thread of
 * its own, while the call waits for it at most its hook timeout. A Java thread cannot be stopped
 * from outside: on the call's own thread a wrapper that hangs would hang the call. So the call
 * waits here instead, and once its time is up it goes on and leaves the wrapper its thread, which
 * returns to this pool if the wrapper ever ends.
 *
 * <p>A fast wrapper costs the call one hand-off to an idle thread of the pool and back (on two or
 * more cores, the call spins for up to {@link #SPIN_NANOS} before it parks, so that a wrapper that
 * ends within that wakes nobody on the way back). Threads are made as needed, up to
 * {@link #MAX_THREADS} (wrappers running or hanging at once), and end after 30 s idle: a
 * container whose hooks have no local synchronous wrapper has none. Safe for concurrent use.
 */
final class LocalWrappers {
  /** Wrappers running (or hanging) at once; a hook call beyond them is not made, and fails. */
  static final int MAX_THREADS = 64;
  private static final boolean SPIN = Runtime.getRuntime().availableProcessors() > 1;
  /** About what a small local wrapper takes with the hand-off; longer ones are waited for parked. */
  private static final long SPIN_NANOS = TimeUnit.MICROSECONDS.toNanos(50);

  private final String name;
  private ThreadPoolExecutor pool; // Guarded by this.
  private boolean closed; // Guarded by this.

  /** @param name the container's, for the threads' names */
  LocalWrappers(String name) {
    this.name = name;
  }

  /** One wrapper's run, and the call that waits for it. */
  private static final class Run implements Runnable {
    private final Runnable wrapper;
    private final Thread waiter = Thread.currentThread();
    private volatile boolean done;
    private volatile boolean parked;

    Run(Runnable wrapper) {
      this.wrapper = wrapper;
    }

    @Override
    public void run() {
      try {
        wrapper.run();
      } finally {
        done = true;
        if (parked) {
          LockSupport.unpark(waiter);
        }
      }
    }
  }

  /**
   * Runs {@code wrapper} on a thread of the pool and waits until it ends or {@code timeoutNanos}
   * have passed, whichever comes first; a wrapper still running then goes on, on its thread.
   *
   * @return true if the wrapper ended in time, false if it still runs (or this thread was
   *     interrupted: its interrupt stays set)
   * @throws RejectedExecutionException if {@link #MAX_THREADS} wrappers run already, or the
   *     container is closing
   */
  boolean run(Runnable wrapper, long timeoutNanos) {
    Run r = new Run(wrapper);
    pool().execute(r);
    long now = System.nanoTime();
    long deadline = now + timeoutNanos;
    if (SPIN) {
      long spinUntil = now + Math.min(SPIN_NANOS, timeoutNanos);
      while (!r.done && System.nanoTime() - spinUntil < 0) {
        Thread.onSpinWait();
      }
    }
    if (r.done) {
      return true;
    }
    r.parked = true; // before looking at done again: the wrapper's thread looks at parked after
    while (!r.done) {
      long left = deadline - System.nanoTime();
      if (left <= 0 || Thread.currentThread().isInterrupted()) {
        return false;
      }
      LockSupport.parkNanos(this, left);
    }
    return true;
  }

  private synchronized ThreadPoolExecutor pool() {
    if (closed) {
      throw new RejectedExecutionException("closed");
    }
    if (pool == null) {
      AtomicInteger n = new AtomicInteger();
      // No queue: a wrapper runs at once on an idle thread or a new one, or is refused.
      pool = new ThreadPoolExecutor(0, MAX_THREADS, 30, TimeUnit.SECONDS, new SynchronousQueue<>(),
          task -> {
            Thread t = new Thread(task, "trade-hooks-" + name + "-local-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
          });
    }
    return pool;
  }

  /** Makes no more threads; wrappers that still run go on, on theirs, to their end. */
  synchronized void close() {
    closed = true;
    if (pool != null) {
      pool.shutdown();
    }
  }
}
