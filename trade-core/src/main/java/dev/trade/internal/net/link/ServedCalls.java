package dev.trade.internal.net.link;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The calls a link's reading thread serves itself ({@link #serveHere}), and the moves of reading
 * to another thread that keep the link read meanwhile: when the {@link ReadWatch} finds a call
 * served for a whole tick, or whole frames waiting behind it ({@link #look}), and at once when a
 * served call waits for a remote reply ({@link #releaseReading}). Each move leaves a thread serving
 * its call; {@link #servedElsewhere} counts them, so that a link's calls cannot take threads
 * without bound (see RemoteCalls.MAX_SERVED_PER_LINK). Safe for concurrent use.
 */
public final class ServedCalls {
  /** What the current thread serves on a link's reading thread, if anything. */
  private static final ThreadLocal<ServedCalls> SERVING = new ThreadLocal<>();
  /**
   * The link whose call the current thread serves, also after reading moved on
   * ({@link #servesOne}).
   */
  private static final ThreadLocal<ServedCalls> CALL_OF = new ThreadLocal<>();

  private final ReadWatch watch;
  private final LinkInput input;
  private final Runnable moveReading;
  // Odd while the reading thread serves a call; each call and each hand-off counts one up, so a
  // stale value never matches a later call.
  private final AtomicLong work = new AtomicLong();
  // The thread whose call 'work' counts while it is odd.
  private volatile Thread worker;
  // Calls whose thread handed reading on and still serves them.
  private final AtomicInteger servedElsewhere = new AtomicInteger();
  // What the watch saw at its last look; read and written by the watch thread only.
  private long watchSeen;

  /**
   * @param input the link's input, to see whether whole frames wait
   * @param moveReading starts reading the link on another thread
   */
  ServedCalls(ReadWatch watch, LinkInput input, Runnable moveReading) {
    this.watch = watch;
    this.input = input;
    this.moveReading = moveReading;
  }

  /**
   * Serves a call on the thread that read it (the reading thread): the call runs without another
   * thread waking up first, and its reply can leave with those of the calls read with it. Should
   * the call take longer than a tick of the {@link ReadWatch}, or wait for a remote reply
   * ({@link #releaseReading}), reading goes on in another thread meanwhile.
   *
   * @return true if this thread still reads the link, false if reading went on elsewhere (then
   *     this thread leaves the read loop)
   */
  boolean serveHere(Runnable call) {
    worker = Thread.currentThread();
    long stamp = work.incrementAndGet();
    watch.serving();
    SERVING.set(this);
    ServedCalls outer = CALL_OF.get(); // a caller reading its reply serves what it reads
    CALL_OF.set(this);
    try {
      call.run();
    } finally {
      SERVING.set(null);
      CALL_OF.set(outer);
    }
    if (work.compareAndSet(stamp, stamp + 1)) {
      return true;
    }
    servedElsewhere.decrementAndGet(); // reading moved on while this call ran: its thread is free
    return false;
  }

  /**
   * Whether the current thread serves a call that came over this link, as its reading thread or,
   * reading having moved on, as the thread left serving it.
   */
  boolean servesOne() {
    return CALL_OF.get() == this;
  }

  /** How many calls of this link are served now by threads that no longer read it. */
  int servedElsewhere() {
    return servedElsewhere.get();
  }

  /**
   * Called by a thread that is about to wait for a remote reply: if it is serving a call on a
   * link's reading thread, reading goes on elsewhere at once, since the reply may come over that
   * very link.
   */
  public static void releaseReading() {
    ServedCalls served = SERVING.get();
    if (served != null) {
      SERVING.set(null);
      long stamp = served.work.get();
      if (served.worker == Thread.currentThread()) {
        served.handOff(stamp);
      }
    }
  }

  /**
   * The watch's look (watch thread only). Hands reading on when the reading thread has served the
   * same call since the last look (a slow call), or serves a call while whole frames wait behind
   * it (a burst that another core can help with). Either costs one thread wake-up, at most once
   * per tick.
   *
   * @return whether the link served any call since the last look
   */
  boolean look() {
    long stamp = work.get();
    boolean serving = (stamp & 1) == 1;
    boolean changed = stamp != watchSeen;
    if (serving && (!changed || input.holdsWholeFrame())) {
      handOff(stamp);
    }
    watchSeen = stamp;
    return changed || serving;
  }

  /** Moves reading to another thread if {@code stamp} is still the call being served. */
  private void handOff(long stamp) {
    if ((stamp & 1) == 1 && work.compareAndSet(stamp, stamp + 1)) {
      servedElsewhere.incrementAndGet();
      moveReading.run();
    }
  }
}
