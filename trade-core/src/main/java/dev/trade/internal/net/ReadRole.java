package dev.trade.internal.net;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Who reads a link: its reading thread, or a caller waiting for its reply over it.
 *
 * <p>A reply read by the link's thread must then be handed to the caller, and on a small machine
 * that hand-off is a third thread per call beside the caller and the provider's reader. So while
 * a lone caller waits for a reply over a link, the link's thread, once it has read all it holds,
 * lends reading to callers and parks ({@link #lend}); the caller reads the link itself
 * ({@link #tryTake}), as a raw socket client reads its own. A caller in a tight loop takes reading
 * again with every call; once callers stop for {@link #LINGER_NANOS}, or one stops early
 * ({@link #giveBack} with {@code wake}), the link's thread takes reading back. So a frame that
 * arrives while no caller reads waits at most about that long.
 *
 * <p>States: {@code READING} (a reading thread has it), {@code FREE} (lent, nobody reads now),
 * {@code LENT} (a caller reads), {@code ENDED} (the link's reading ended). Only the holder leaves
 * {@code READING} or {@code LENT}, except that a hand-off's new thread takes reading over from a
 * holder that serves a call ({@link #takenOver}). Safe for concurrent use.
 */
final class ReadRole {
  /** How long reading stays lent after a caller last took it. */
  static final long LINGER_NANOS = TimeUnit.MICROSECONDS.toNanos(200);
  private static final int READING = 0;
  private static final int FREE = 1;
  private static final int LENT = 2;
  private static final int ENDED = 3;

  private final AtomicInteger state = new AtomicInteger(READING);
  /** Callers that will read their replies themselves, from before they send until they stop. */
  private final AtomicInteger borrowers = new AtomicInteger();
  /** The thread that lent reading and waits to take it back. */
  private volatile Thread lender;
  private volatile long lastTaken = System.nanoTime();
  /** A caller stopped while others may wait: the lender takes reading back at once. */
  private volatile boolean wanted;
  /** The link is closed: the lender takes reading back at once, to end it. */
  private volatile boolean closing;

  /** Whether a caller is about to read (asked by the reading thread between frames). */
  boolean callerWaits() {
    return borrowers.get() > 0;
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
        long idle = System.nanoTime() - lastTaken;
        boolean waiting = borrowers.get() > 0;
        boolean back = wanted || closing || !waiting && idle >= LINGER_NANOS;
        if (back && s == FREE && state.compareAndSet(FREE, READING)) {
          wanted = false;
          return true;
        }
        // Until the linger is over, or (callers about) until a caller takes, stops or wakes us.
        LockSupport.parkNanos(this, back || waiting ? LINGER_NANOS : LINGER_NANOS - idle);
      }
    } finally {
      if (lender == self) {
        lender = null;
      }
    }
  }

  /** Counts a caller that will read its own reply; before it sends its call. */
  void borrow() {
    borrowers.incrementAndGet();
  }

  /**
   * Ends a {@link #borrow}.
   *
   * @param wake whether the lender should read again at once: the caller still waits, or other
   *     callers do, and their replies must not wait for the linger
   */
  void giveBack(boolean wake) {
    borrowers.decrementAndGet();
    if (wake) {
      wanted = true;
      wakeLender();
    }
  }

  /** A caller takes reading if nobody reads; then it must {@link #release} it or end it. */
  boolean tryTake() {
    if (state.get() == FREE && state.compareAndSet(FREE, LENT)) {
      lastTaken = System.nanoTime();
      return true;
    }
    return false;
  }

  /** The caller that took reading stops reading; the lender (or the next caller) goes on. */
  void release() {
    state.set(FREE);
    if (wanted) {
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

  /** Whether a caller reads now (for tests). */
  boolean isCallerReading() {
    return state.get() == LENT;
  }
}
