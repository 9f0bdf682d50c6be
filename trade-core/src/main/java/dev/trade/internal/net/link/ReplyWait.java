package dev.trade.internal.net.link;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * How a caller waits for its reply. A lone caller reads the link itself when reading is lent to
 * callers (see {@link ReadRole}): the reply then wakes no thread on its way to the caller, which
 * saves one or two thread wake-ups (5-20 us each on a small machine, more after a pause) per
 * call. If its replies have lately come back within {@link #MAX_SPIN_NANOS}, it waits actively for
 * about two round trips; a reply later than that (or any reply, on one core) it waits for in a
 * read of its own for up to {@link #BLOCK_NANOS}, so that the reply wakes it directly, as a raw
 * socket's caller is woken, not through the link's thread; then it parks. Should the link's
 * thread still read when the reply comes, it hands the reply over. Many callers at once park at
 * once: their spinning would take the cores that produce the replies. Safe for concurrent use.
 */
public final class ReplyWait {
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

  public ReplyWait() {
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
   * Before a call is sent over {@code link}: whether its caller will likely wait alone, and so
   * read its reply itself (unless it calls more seldom than lending pays for, see
   * {@link ReadRole#lendingPays}); then it is counted on the link ({@link ReadRole#borrow}), and
   * must pass true to {@link #await} or {@link #abandon}.
   */
  public boolean borrow(Link link) {
    if (waiting.get() == 0) {
      if (link.role.lendingPays()) {
        link.role.borrow();
        return true;
      }
      link.role.touch();
    }
    return false;
  }

  /** The call was not sent after all: ends its {@link #borrow}. */
  public void abandon(Link link, boolean borrowed) {
    if (borrowed) {
      link.role.giveBack(true);
    }
  }

  /**
   * Waits for {@code reply} to the call sent over {@code link}. Without a timeout of its own: the
   * call's deadline completes {@code reply} when it passes (Deadlines).
   *
   * @param borrowed what {@link #borrow} said for the call
   * @param sent when the call was sent ({@link System#nanoTime})
   */
  public byte[] await(Link link, boolean borrowed, CompletableFuture<byte[]> reply, long sent)
      throws ExecutionException, InterruptedException {
    try {
      boolean lone = waiting.getAndIncrement() == 0;
      long estimate = roundTrip;
      boolean spin = lone && SPIN && estimate < MAX_SPIN_NANOS;
      long until = sent + Math.min(MAX_SPIN_NANOS, 2 * estimate);
      if (borrowed) {
        if (spin) {
          link.reader.readFor(reply, until);
        }
        if (!reply.isDone() && lone && waiting.get() == 1) {
          link.reader.blockFor(reply, System.nanoTime() + blockNanos);
        }
      } else if (spin) {
        while (!reply.isDone() && System.nanoTime() - until < 0) {
          Thread.onSpinWait();
        }
      }
      byte[] result = parkFor(link, reply);
      long took = System.nanoTime() - sent;
      roundTrip += (Math.min(took, 16 * MAX_SPIN_NANOS) - roundTrip) >> 3;
      return result;
    } finally {
      if (borrowed && link.servesCallOnThisThread()) {
        // A call back to the peer whose call this thread serves: the peer's next call comes only
        // after this thread's reply, and must not find reading lent to nobody.
        link.role.giveBackCallingBack();
      } else if (borrowed) {
        // Once it has its reply (so a control loop's next call finds reading lent, see ReadRole);
        // if others wait, the link's thread reads again at once: nobody may read for them now.
        link.role.giveBack(waiting.get() > 1);
      }
      waiting.decrementAndGet();
    }
  }

  /** Parks until {@code reply} is done; the link is not left lent meanwhile (nobody would read). */
  private static byte[] parkFor(Link link, CompletableFuture<byte[]> reply)
      throws ExecutionException, InterruptedException {
    if (!reply.isDone()) {
      ReadRole role = link.role;
      role.parking();
      // Uncounted by the thread that completes the reply, before it reads on: a link's thread
      // that hands this reply over must find no caller parked, and lend reading again, or the
      // caller's next call would find it blocked in a read and be handed its reply once more.
      reply.whenComplete((r, e) -> role.unparked());
    }
    return reply.get();
  }
}
