package dev.trade.internal.net;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * How a caller waits for its reply. A lone caller whose replies have lately come back within
 * {@link #MAX_SPIN_NANOS} waits actively for about two round trips, and reads the link itself
 * meanwhile (see {@link ReadRole}): the reply then wakes no thread on its way to the caller, which
 * saves one or two thread wake-ups (5-20 us each on a small machine) per call. A reply later than
 * that it waits for in a read of its own for up to {@link #BLOCK_NANOS}, so that the reply wakes
 * it directly, not through the link's thread; then it parks. Should the link's thread still read
 * when the reply comes, it hands the reply over without waking the caller. Many callers at once
 * park at once: their spinning would take the cores that produce the replies. Safe for concurrent
 * use.
 */
final class ReplyWait {
  /** Spinning only helps when another core can run the threads that bring the reply. */
  private static final boolean SPIN = Runtime.getRuntime().availableProcessors() > 1;
  /** The longest a caller spins before it parks; replies slower than this are not waited for so. */
  private static final long MAX_SPIN_NANOS = TimeUnit.MICROSECONDS.toNanos(100);
  /** How long a lone caller that spun in vain waits in a read of its own before it parks. */
  private static final long BLOCK_NANOS = TimeUnit.MILLISECONDS.toNanos(1);

  private final long blockNanos;
  /** Callers waiting for a reply; only a lone one spins. */
  private final AtomicInteger waiting = new AtomicInteger();
  /** A running average of recent round trips (ns); racy updates are fine for an estimate. */
  private volatile long roundTrip = MAX_SPIN_NANOS / 2;

  ReplyWait() {
    this(BLOCK_NANOS);
  }

  /** @param blockNanos how long a lone caller waits in a read (tests give it longer) */
  ReplyWait(long blockNanos) {
    this.blockNanos = blockNanos;
  }

  /** How many callers wait now (for tests). */
  int waiting() {
    return waiting.get();
  }

  /**
   * Before a call is sent over {@code link}: whether its caller will likely wait alone and
   * actively, and so read its reply itself; then it is counted on the link
   * ({@link ReadRole#borrow}), and must pass true to {@link #await} or {@link #abandon}.
   */
  boolean borrow(Link link) {
    if (SPIN && waiting.get() == 0 && roundTrip < MAX_SPIN_NANOS) {
      link.role.borrow();
      return true;
    }
    return false;
  }

  /** The call was not sent after all: ends its {@link #borrow}. */
  void abandon(Link link, boolean borrowed) {
    if (borrowed) {
      link.role.giveBack(true);
    }
  }

  /**
   * Waits for {@code reply} to the call sent over {@code link}. Without a timeout of its own: the
   * call's deadline completes {@code reply} when it passes ({@link Deadlines}).
   *
   * @param borrowed what {@link #borrow} said for the call
   * @param sent when the call was sent ({@link System#nanoTime})
   */
  byte[] await(Link link, boolean borrowed, CompletableFuture<byte[]> reply, long sent)
      throws ExecutionException, InterruptedException {
    try {
      boolean lone = waiting.getAndIncrement() == 0;
      long estimate = roundTrip;
      try {
        if (lone && SPIN && estimate < MAX_SPIN_NANOS) {
          long until = sent + Math.min(MAX_SPIN_NANOS, 2 * estimate);
          if (borrowed) {
            link.reader.readFor(reply, until);
            if (!reply.isDone() && waiting.get() == 1) {
              link.reader.blockFor(reply, System.nanoTime() + blockNanos);
            }
          } else {
            while (!reply.isDone() && System.nanoTime() - until < 0) {
              Thread.onSpinWait();
            }
          }
        }
      } finally {
        if (borrowed) {
          // The link's thread reads again at once if this caller goes on waiting (parked), or
          // if others wait: nobody may read for them now.
          link.role.giveBack(!reply.isDone() || waiting.get() > 1);
        }
      }
      byte[] result = reply.get();
      long took = System.nanoTime() - sent;
      roundTrip += (Math.min(took, 16 * MAX_SPIN_NANOS) - roundTrip) >> 3;
      return result;
    } finally {
      waiting.decrementAndGet();
    }
  }
}
