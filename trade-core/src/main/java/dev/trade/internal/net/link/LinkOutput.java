package dev.trade.internal.net.link;

import java.io.IOException;
import java.io.OutputStream;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

/**
 * A link's writing. A sender that finds the socket idle writes its frame itself (no thread
 * hand-off on the latency path); senders that arrive while a write is in progress only queue
 * their frame, and the writing thread drains the queue before it flushes, so concurrent calls
 * share system calls. No lock: with many callers on one link, a lock here made them queue for it
 * and sleep.
 *
 * <p>While the link's reader hands out frames read together (a burst: calls it serves, replies
 * that wake callers who call again at once), what they send is left for the reader to write once
 * it has handed them all out ({@link #endBurst}), in one system call.
 *
 * <p>A slow peer is not a dead one: the bytes go out in pieces, each timed ({@link #writingSince}).
 * Its queue is bounded for calls ({@link #ROOM}), and on it the calls nobody waits for any more
 * are left out ({@link #CONGESTED}, {@link #offerPassedOn}); a caller or the control thread that
 * finds itself writing for others on it stops after {@link #BUDGET} ({@link #write(boolean)}).
 *
 * <p>Safe for concurrent use.
 */
public final class LinkOutput {
  private final OutputStream out;
  private final FrameCipher cipher;
  private final Runnable written;
  /**
   * The most written to the socket in one go: a write that does not end within FAILURETIMEOUT is
   * one of at most this many bytes (or what the link's buffer holds) that the peer does not take.
   * Not less: with 64 KiB pieces, 1 MiB calls took about 15 % longer (p50, three A/B runs).
   */
  static final int PIECE = 1024 * 1024;

  /**
   * Frames of this many bytes queued and not yet written make new calls wait ({@link #awaitRoom}):
   * a peer that takes them slower than they are sent must not make the queue grow without bound.
   */
  static final long ROOM = 16 << 20;
  /** From this many bytes waiting on, the writer leaves out frames nobody waits for any more. */
  static final long CONGESTED = 256 << 10;
  /** How long a thread with work of its own writes for others ({@link #write(boolean)}). */
  static final long BUDGET = TimeUnit.MILLISECONDS.toNanos(1);

  private final Queue<byte[]> queue = new ConcurrentLinkedQueue<>();
  /** Bytes of the frames offered and not yet handed to the stream (taken off in batches). */
  private final AtomicLong queued = new AtomicLong();
  private final long room;
  private final Predicate<byte[]> abandoned;
  /** CALLs passed on for other containers, stamped with when they are due (offerPassedOn). */
  private final Set<byte[]> passedOn = ConcurrentHashMap.newKeySet();
  /** Senders in {@link #awaitRoom}, waiting on this. */
  private final Object roomLock = new Object();
  private volatile int roomWaiters;
  private final AtomicBoolean writing = new AtomicBoolean();
  /** Whether the reader hands out frames read together with more; see leftForBurst. */
  private volatile boolean burst;
  /** Whether a frame was sent, and perhaps left for the end of a burst, since the last look. */
  private volatile boolean deferred;
  /** Set once {@link Link#GOODBYE} is written: nothing is written after it. */
  private volatile boolean saidGoodbye;
  /**
   * While a thread writes, when it last moved on (nanoTime, never 0): before its current write to
   * the socket, or shortly before; 0 when nobody writes. A peer that stops reading stalls a write
   * for good once its socket buffers are full: the heartbeat closes such a link
   * ({@link #writingSince}), which ends the write with an exception. A slow peer that reads all
   * along is not stalled, however long a long queue or a large frame takes to drain, so the time is
   * taken again as the bytes go out: at least every {@link #PIECE} bytes.
   */
  private volatile long writingSince;

  /**
   * @param cipher seals each frame as it is written; null when the link is not encrypted
   * @param written runs after each flush
   */
  LinkOutput(OutputStream out, FrameCipher cipher, Runnable written) {
    this(out, cipher, written, ROOM, frame -> false);
  }

  /**
   * @param room bytes queued and not yet written from which on new calls wait ({@link #ROOM})
   * @param abandoned whether a queued frame need not go out any more (see
   *     {@link LinkHandler#abandoned}); asked only while {@link #CONGESTED}
   */
  LinkOutput(OutputStream out, FrameCipher cipher, Runnable written, long room,
      Predicate<byte[]> abandoned) {
    this.out = out;
    this.cipher = cipher;
    this.written = written;
    this.room = room;
    this.abandoned = abandoned;
  }

  /** Queues a complete frame (header included) for the next {@link #write(boolean)}. */
  void offer(byte[] frame) {
    queued.addAndGet(frame.length);
    queue.offer(frame);
  }

  /** Takes back a frame {@link #offer}ed and not written yet; false if it was written. */
  boolean withdraw(byte[] frame) {
    if (!queue.remove(frame)) {
      return false;
    }
    passedOn.remove(frame);
    queued.addAndGet(-frame.length);
    return true;
  }

  /**
   * Queues a CALL that another container made, passing it on: stamped with when it is due
   * ({@link Frames#stampDue}), from its arrival here. The writer leaves it out once its time is up
   * (its caller has given up) and else tells the next container the time then left. Not for the
   * calls made here: their callers' deadlines say when they are given up ({@link #abandoned}),
   * and a clock read per call cost a few per cent with many callers.
   */
  void offerPassedOn(byte[] call) {
    Frames.stampDue(call, nowMillis());
    passedOn.add(call);
    offer(call);
  }

  /** A clock in ms for {@link Frames#stampDue}: nanoTime's, cut to 32 bits (it wraps around). */
  private static int nowMillis() {
    return (int) Math.floorDiv(System.nanoTime(), 1_000_000L);
  }

  /** Whether the frames waiting to be written come to less than the room: a call may queue. */
  public boolean hasRoom() {
    return queued.get() < room;
  }

  /** Bytes of the frames queued and not yet written (approximately: taken off in batches). */
  public long queuedBytes() {
    return queued.get();
  }

  /**
   * Waits until there is room ({@link #hasRoom}), the link is {@code closed}, or {@code deadline}
   * ({@link System#nanoTime}) passes.
   *
   * @return false if the deadline passed first
   */
  public boolean awaitRoom(long deadline, BooleanSupplier closed) throws InterruptedException {
    synchronized (roomLock) {
      roomWaiters++; // before looking at the queue again: see wakeRoomWaiters
      try {
        while (!hasRoom() && !closed.getAsBoolean()) {
          long left = deadline - System.nanoTime();
          if (left <= 0) {
            return false;
          }
          TimeUnit.NANOSECONDS.timedWait(roomLock, left);
        }
        return true;
      } finally {
        roomWaiters--;
      }
    }
  }

  /**
   * Wakes the senders waiting for room: there is some now, or the link closed. A waiter counts
   * itself before it looks at the queue, so one that missed this call saw the room it was for.
   */
  void wakeRoomWaiters() {
    if (roomWaiters > 0) {
      synchronized (roomLock) {
        roomLock.notifyAll();
      }
    }
  }

  /**
   * Writing went on: notes when, and takes {@code done} bytes written off the queued ones.
   *
   * @return the time ({@link System#nanoTime})
   */
  private long progressed(long done) {
    long now = System.nanoTime();
    writingSince = now | 1;
    if (done != 0 && queued.addAndGet(-done) < room) {
      wakeRoomWaiters();
    }
    return now;
  }

  /**
   * After {@link #offer}: whether the frame is left for the reader, which is handing out a burst
   * and writes it at the burst's end; if not, the sender writes.
   */
  boolean leftForBurst() {
    deferred = true; // before looking at burst, see endBurst
    if (burst) {
      // Whoever reads after this burst sees the frame too, as a burst ends before then.
      return true;
    }
    deferred = false;
    return false;
  }

  /** The reader is about to hand out a frame; {@code more} whether more wait read behind it. */
  void burst(boolean more) {
    burst = more;
  }

  /**
   * Ends a burst (reader, before it may block in a read).
   *
   * @return whether frames were left for it: then it must {@link #write(boolean)}
   */
  boolean endBurst() {
    burst = false; // before looking at deferred: a sender that saw burst true set it before this
    if (!deferred) {
      return false; // what others queued (the control thread's floods) they write themselves
    }
    deferred = false;
    return true;
  }

  /**
   * Writes and flushes every queued frame, unless another thread is writing: that one writes them.
   * {@code budgeted}: this thread has work of its own (a caller, the control thread, a link's
   * reader) and stops, between frames, once it has written for {@link #BUDGET} while others keep
   * queueing. Else a slow link kept busy would hold it writing for everyone as
   * long as that lasts, a caller far past its deadline.
   *
   * @return true if it stopped so with frames left: the caller must see them written elsewhere
   * @throws IOException if a write failed; what was queued is dropped (the link is to close)
   */
  boolean write(boolean budgeted) throws IOException {
    while (!saidGoodbye && !queue.isEmpty() && writing.compareAndSet(false, true)) {
      long began = System.nanoTime();
      writingSince = began | 1;
      boolean over = false; // found over budget at the last clock read
      try {
        int untimed = 0; // bytes handed to the stream since writingSince was taken
        long done = 0; // bytes of whole frames handed to the stream, still counted as queued
        byte[] next;
        while (!(budgeted && over) && !saidGoodbye && (next = queue.poll()) != null) {
          boolean left = !passedOn.isEmpty() && passedOn.remove(next)
              ? !Frames.unstampDue(next, nowMillis())
              : queued.get() >= CONGESTED && abandoned.test(next);
          if (left) {
            done += next.length; // a call whose caller went on without it: left out
            untimed += next.length; // and soon off the count
            continue;
          }
          // Sealing here, in write order, keeps the cipher's frame counter in step with the wire.
          byte[] bytes = cipher == null ? next : cipher.seal(next);
          for (int at = 0; at < bytes.length; ) {
            if (untimed >= Link.BUFFER) {
              // What went before left (or waits in the buffer), and this thread moves on: not
              // stalled. Not for every small frame: one clock read per buffer's worth will do.
              over = progressed(done) - began > BUDGET;
              done = 0;
              untimed = 0;
            }
            int n = Math.min(PIECE, bytes.length - at);
            out.write(bytes, at, n);
            at += n;
            untimed += n;
          }
          done += next.length;
          if (next == Link.GOODBYE) {
            saidGoodbye = true; // the last frame: what follows stays queued
          }
        }
        if (untimed > 0 || done > 0) {
          progressed(done);
        }
        if (budgeted && over && !saidGoodbye && !queue.isEmpty()) {
          return true; // the rest, and the flush, are for whoever writes next
        }
        out.flush();
        written.run();
      } catch (IOException e) {
        queue.clear();
        passedOn.clear();
        queued.set(0);
        wakeRoomWaiters();
        throw e;
      } finally {
        writingSince = 0;
        writing.set(false);
      }
      // A frame queued after our last poll by a sender that found us writing is ours: look again.
    }
    return false;
  }

  /** When the writer last moved on ({@link System#nanoTime}), or 0 if nobody writes now. */
  long writingSince() {
    return writingSince;
  }

  /** Whether nothing is left to write (all queued was written, or GOODBYE was) and nobody writes. */
  boolean drained() {
    return (queue.isEmpty() || saidGoodbye) && !writing.get();
  }
}
