package dev.trade.internal.net.link;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.LongSupplier;
import java.util.concurrent.locks.LockSupport;

/**
 * Who reads a link: its reading thread, or a caller waiting for its reply over it.
 *
 * <p>A reply read by the link's thread must then be handed to the caller, and on a small machine
 * that hand-off is a third thread per call beside the caller and the provider's reader; after a
 * pause it also wakes the caller on the other core, which sleeps. So while a lone caller waits for
 * a reply over a link, or has lately called over it, the link's thread, once it has read all it
 * holds, lends reading to callers and parks ({@link #lend}); the caller reads the link itself
 * ({@link #tryTake}), as a raw socket client reads its own. A caller in a loop, back to back or
 * once a millisecond like a control loop, takes reading again with every call; once callers stop
 * for the linger, or one stops early ({@link #giveBack} with {@code wake}), or a caller that does
 * not read waits for a reply ({@link #parking}), the link's thread takes reading back. The linger
 * follows the lone caller's period: twice its last, from {@link #MIN_LINGER_NANOS} to
 * {@link #LINGER_NANOS}; a caller calling more seldom than that does not borrow
 * ({@link #lendingPays}). So a frame that arrives while no caller reads (a ping, the peer's own
 * call) waits at most about that long, only on a link a lone caller uses, and up to 2 ms only
 * while a caller calls at least every 2 ms, when lending pays. A caller that calls back the peer
 * whose call it serves over this link (a hook whose wrapper is in the caller's container, any
 * re-entrant call) ends the linger as it gives reading back ({@link #giveBackCallingBack}): the
 * peer's next call, which only its reply lets the peer make, would always wait for it.
 *
 * <p>States: {@code READING} (a reading thread has it), {@code FREE} (lent, nobody reads now),
 * {@code LENT} (a caller reads), {@code ENDED} (the link's reading ended). Only the holder leaves
 * {@code READING} or {@code LENT}, except that a hand-off's new thread takes reading over from a
 * holder that serves a call ({@link #takenOver}). Safe for concurrent use.
 */
final class ReadRole {
  /**
   * The longest reading stays lent after a caller last borrowed, took or gave it back: longer
   * than a 1 kHz control loop's pause between calls with its jitter, so that such a loop finds it
   * lent at every call.
   */
  static final long LINGER_NANOS = TimeUnit.MILLISECONDS.toNanos(2);
  /** The shortest: a loop calling back to back, or slower than lending pays for. */
  static final long MIN_LINGER_NANOS = TimeUnit.MICROSECONDS.toNanos(200);
  private static final int READING = 0;
  private static final int FREE = 1;
  private static final int LENT = 2;
  private static final int ENDED = 3;

  private final long minLinger;
  private final long maxLinger;
  /** {@link System#nanoTime}, or a test's clock. */
  private final LongSupplier clock;
  private final AtomicInteger state = new AtomicInteger(READING);
  /** Callers that will read their replies themselves, from before they send until they stop. */
  private final AtomicInteger borrowers = new AtomicInteger();
  /** Callers that wait for a reply without reading: reading must not stay lent meanwhile. */
  private final AtomicInteger parked = new AtomicInteger();
  /** The thread that lent reading and waits to take it back. */
  private volatile Thread lender;
  /** When a caller last borrowed, took or gave back reading; long ago at first. */
  private volatile long lastActive;
  /** When a lone caller last called, borrowing or not; long ago at first. */
  private volatile long lastCall;
  /** How long reading stays lent now, after the lone caller's last pause (see the class). */
  private volatile long linger;
  /** A caller stopped while others may wait: the lender takes reading back at once. */
  private volatile boolean wanted;
  /** The link is closed: the lender takes reading back at once, to end it. */
  private volatile boolean closing;

  ReadRole() {
    this(MIN_LINGER_NANOS, LINGER_NANOS, System::nanoTime);
  }

  /**
   * @param minLinger, maxLinger the bounds of the linger (tests give others)
   * @param clock the time in nanoseconds, as {@link System#nanoTime} (tests give their own)
   */
  ReadRole(long minLinger, long maxLinger, LongSupplier clock) {
    this.minLinger = minLinger;
    this.maxLinger = maxLinger;
    this.clock = clock;
    this.linger = minLinger;
    this.lastActive = clock.getAsLong() - 2 * maxLinger;
    this.lastCall = lastActive;
  }

  /** Whether a caller is about to read (for tests). */
  boolean callerWaits() {
    return borrowers.get() > 0;
  }

  /**
   * Whether the reading thread, with nothing left to read, should lend reading: a caller is about
   * to read, or one was about within the linger and may call again, and no caller waits for a
   * reply that only a reading thread would read.
   */
  boolean shouldLend() {
    return parked.get() == 0
        && (borrowers.get() > 0 || clock.getAsLong() - lastActive < linger);
  }

  /**
   * The reading thread lends reading to callers and parks until it is to read again.
   *
   * @return true once this thread reads again; false if another thread reads now or reading ended
   */
  boolean lend() {
    Thread self = Thread.currentThread();
    lender = self;
    state.set(FREE);
    try {
      while (true) {
        int s = state.get();
        if (s == READING || s == ENDED) {
          return false;
        }
        long idle = clock.getAsLong() - lastActive;
        long lingering = linger;
        boolean waiting = borrowers.get() > 0;
        boolean back = wanted || closing || parked.get() > 0 || !waiting && idle >= lingering;
        if (back && s == FREE && state.compareAndSet(FREE, READING)) {
          wanted = false;
          return true;
        }
        // Until the linger is over, or (callers about) until a caller takes, stops or wakes us.
        LockSupport.parkNanos(this, back || waiting ? lingering : lingering - idle);
      }
    } finally {
      if (lender == self) {
        lender = null;
      }
    }
  }

  /**
   * Whether a lone caller about to call should borrow reading: only if the last lone call began
   * no longer ago than the longest linger, so that a loop calling that often finds reading lent.
   * A slower caller's reply is read by the link's thread, with no lending after it that would not
   * reach its next call; it {@link #touch}es instead.
   */
  boolean lendingPays() {
    return clock.getAsLong() - lastCall <= maxLinger;
  }

  /** A lone caller that does not borrow calls now: the next call's period counts from here. */
  void touch() {
    lastCall = clock.getAsLong();
  }

  /** Counts a caller that will read its own reply; before it sends its call. */
  void borrow() {
    borrowers.incrementAndGet();
    long now = clock.getAsLong();
    long period = now - lastCall; // since the last lone call began
    linger = period > maxLinger ? minLinger : Math.max(minLinger, Math.min(maxLinger, 2 * period));
    lastCall = now;
    lastActive = now;
  }

  /**
   * A caller is about to wait for a reply over this link without reading it: if reading is lent,
   * the lender reads again at once, and lends no more until {@link #unparked}.
   */
  void parking() {
    parked.incrementAndGet();
    int s = state.get();
    if (s == FREE || s == LENT) {
      wakeLender(); // if LENT, the caller that reads wakes it too as it stops (release)
    }
  }

  /** Ends a {@link #parking}: the caller has its reply, or stopped waiting. */
  void unparked() {
    parked.decrementAndGet();
  }

  /**
   * Ends a {@link #borrow}, once the caller has its reply (or its call failed or was not sent):
   * the linger counts from here.
   *
   * @param wake whether the lender should read again at once: other callers wait, and their
   *     replies must not wait for the linger
   */
  void giveBack(boolean wake) {
    lastActive = clock.getAsLong();
    borrowers.decrementAndGet();
    if (wake) {
      wanted = true;
      wakeLender();
    }
  }

  /**
   * Ends a {@link #borrow} whose caller will not call again before the peer sends something: it
   * called back the peer whose call it serves. The peer's next frame (its next call, which only
   * this caller's reply lets it make) would come while reading lingers lent to a caller that will
   * not read, and wait for the linger. So the linger ends here, and the lender reads again at once
   * (unless other callers still borrow).
   */
  void giveBackCallingBack() {
    lastActive = clock.getAsLong() - maxLinger; // at least the linger ago: lending no longer pays
    borrowers.decrementAndGet();
    wakeLender();
  }

  /** A caller takes reading if nobody reads; then it must {@link #release} it or end it. */
  boolean tryTake() {
    if (state.get() == FREE && state.compareAndSet(FREE, LENT)) {
      lastActive = clock.getAsLong();
      return true;
    }
    return false;
  }

  /** The caller that took reading stops reading; the lender (or the next caller) goes on. */
  void release() {
    state.set(FREE);
    if (wanted || parked.get() > 0) {
      wakeLender();
    }
  }

  /** A hand-off's new thread reads now, in place of a holder that serves a call. */
  void takenOver() {
    state.set(READING);
  }

  /** The link's reading ended (its holder closes it); a lender stops waiting. */
  void ended() {
    state.set(ENDED);
    wakeLender();
  }

  /** The link was closed: the lender reads again at once, to end it. */
  void closing() {
    closing = true;
    wakeLender();
  }

  private void wakeLender() {
    Thread t = lender;
    if (t != null) {
      LockSupport.unpark(t);
    }
  }

  /** Whether reading is lent to callers now (for tests). */
  boolean isLent() {
    int s = state.get();
    return s == FREE || s == LENT;
  }

  /** How long reading stays lent now (for tests). */
  long linger() {
    return linger;
  }

  /** Callers waiting for a reply over the link without reading (for tests). */
  int parked() {
    return parked.get();
  }

  /** Whether a caller reads now (for tests). */
  boolean isCallerReading() {
    return state.get() == LENT;
  }
}
