package dev.trade.internal.net;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * How a caller waits for its reply. A lone caller whose replies have lately come back within
 * {@link #MAX_SPIN_NANOS} spins for about two round trips before it parks: the link's reading thread
 * then hands it the reply without waking it, which saves a thread wake-up (5-20 us on a small
 * machine) per call. Many callers at once park at once: their spinning would take the cores that
 * produce the replies. Safe for concurrent use.
 */
final class ReplyWait {
  /** Spinning only helps when another core can run the threads that bring the reply. */
  private static final boolean SPIN = Runtime.getRuntime().availableProcessors() > 1;
  /** The longest a caller spins before it parks; replies slower than this are not waited for so. */
  private static final long MAX_SPIN_NANOS = TimeUnit.MICROSECONDS.toNanos(100);

  /** Callers waiting for a reply; only a lone one spins. */
  private final AtomicInteger waiting = new AtomicInteger();
  /** A running average of recent round trips (ns); racy updates are fine for an estimate. */
  private volatile long roundTrip = MAX_SPIN_NANOS / 2;

  /** How many callers wait now (for tests). */
  int waiting() {
    return waiting.get();
  }

  /**
   * Waits for {@code reply} until the deadline.
   *
   * @param sent when the call was sent ({@link System#nanoTime})
   */
  byte[] await(CompletableFuture<byte[]> reply, long sent, long deadlineNanos)
      throws TimeoutException, ExecutionException, InterruptedException {
    try {
      if (waiting.getAndIncrement() == 0 && SPIN) {
        long estimate = roundTrip;
        if (estimate < MAX_SPIN_NANOS) {
          long until = sent + Math.min(MAX_SPIN_NANOS, 2 * estimate);
          while (!reply.isDone() && System.nanoTime() - until < 0) {
            Thread.onSpinWait();
          }
        }
      }
      byte[] result = reply.isDone() ? reply.get()
          : reply.get(Math.max(0, deadlineNanos - System.nanoTime()), TimeUnit.NANOSECONDS);
      long took = System.nanoTime() - sent;
      roundTrip += (Math.min(took, 16 * MAX_SPIN_NANOS) - roundTrip) >> 3;
      return result;
    } finally {
      waiting.decrementAndGet();
    }
  }
}
