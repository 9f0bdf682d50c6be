package dev.trade.internal.net.link;

import java.util.Collection;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * Keeps every link read while calls are served on the threads that read them.
 *
 * <p>A link's reading thread serves a call itself (see {@link ServedCalls#serveHere}): no other thread has
 * to wake up before the call runs or after it, which is most of a small call's cost. While it
 * serves, nobody reads that link. This watch looks at the links once per tick (about a
 * millisecond) and, when a link's thread has been serving the same call for a whole tick, hands
 * reading to a thread of the executor; the serving thread leaves the read loop when its call ends.
 * So a slow or blocked service delays the frames behind it on its link by one to two ticks, never
 * its heartbeats by more, and fast calls never pay for a hand-off. The same thing happens at once
 * when a served call itself waits for a remote reply ({@link ServedCalls#releaseReading}).
 *
 * <p>The watch ticks only while calls are being served: after a few ticks without any, it parks
 * until the next one starts, so idle containers (and a hundred of them on one host) cost nothing,
 * and its thread starts with the first served call, so a container that serves none has none,
 * and a container answering a control loop's calls at 10 to 100 Hz wakes it a few times per call,
 * not a thousand times a second. Under a steady stream of calls it ticks once a millisecond and
 * nobody wakes it. Safe for concurrent use.
 */
public final class ReadWatch implements AutoCloseable {
  private static final long TICK_NANOS = TimeUnit.MILLISECONDS.toNanos(1);
  /**
   * Ticks without any served call before the watch parks. Waking it costs the next call's thread
   * a system call (a microsecond or two), so it should outlast short pauses between calls.
   */
  private static final int IDLE_TICKS = 8;

  private final Collection<Link> links;
  private final Executor executor;
  private final String name;
  private volatile Thread thread; // from the first served call on
  private volatile boolean parked;
  private volatile boolean closed;

  /**
   * @param links the live links, looked at on every tick
   * @param executor runs a link's read loop when reading is handed on
   */
  public ReadWatch(Collection<Link> links, Executor executor, String name) {
    this.links = links;
    this.executor = executor;
    this.name = name;
  }

  /**
   * Called by a link's reading thread as it starts serving a call: wakes the watch if it sleeps,
   * starts it at the first call.
   */
  void serving() {
    Thread t = thread;
    if (t == null) {
      start();
    } else if (parked) {
      LockSupport.unpark(t);
    }
  }

  private synchronized void start() {
    if (thread == null && !closed) {
      Thread t = new Thread(this::run, "trade-readwatch-" + name);
      t.setDaemon(true);
      t.start();
      thread = t; // after start: a concurrent serving() must not unpark a thread not yet started
    }
  }

  /** Whether the watch sleeps until the next served call, or has not started yet (for tests). */
  boolean isParked() {
    Thread t = thread;
    return t == null || parked && t.getState() == Thread.State.WAITING;
  }

  /** Whether the watch's thread has started (for tests). */
  boolean isStarted() {
    return thread != null;
  }

  /**
   * Runs {@code link}'s read loop on a thread of the executor.
   *
   * @return false if the executor refused (the container is closing)
   */
  boolean read(Runnable readLoop) {
    try {
      executor.execute(readLoop);
      return true;
    } catch (RejectedExecutionException closing) {
      return false;
    }
  }

  private void run() {
    int idle = 0; // started by a call: watch it
    while (!closed) {
      if (tick()) {
        idle = 0;
      } else if (++idle >= IDLE_TICKS) {
        parked = true;
        // A call that started before 'parked' was set found it false and did not wake us: look once
        // more before sleeping. One that starts after sees it true and unparks us.
        if (!tick() && !closed) {
          LockSupport.park(this);
        }
        parked = false;
        idle = 0;
        continue;
      }
      LockSupport.parkNanos(this, TICK_NANOS);
    }
  }

  /** One look at every link; true if any served a call since the last look. */
  private boolean tick() {
    boolean busy = false;
    for (Link l : links) {
      busy |= l.watch();
    }
    return busy;
  }

  @Override
  public synchronized void close() {
    closed = true;
    Thread t = thread;
    if (t != null) {
      LockSupport.unpark(t);
    }
  }
}
