package dev.trade.internal.net.link;

import java.util.concurrent.atomic.AtomicLong;

/**
 * How much of one link's replication frames waits for the control thread. Bounded: the link's
 * thread reads on while the control thread applies, so without a bound a member that sends
 * frames faster than they are applied (table requests without end, say, while the answers pile up
 * unread) would fill this container's memory. Safe for concurrent use.
 */
public final class ControlBacklog {
  /** What a queued frame holds beyond its payload (the task, the array's header): an estimate. */
  public static final int PER_FRAME = 128;

  private final AtomicLong held = new AtomicLong();

  /**
   * Counts a frame of {@code payloadLength} bytes in.
   *
   * @return what to {@link #release} once it is applied, or -1 when it would take the backlog
   *     beyond {@code limit} (then nothing is counted)
   */
  public long hold(int payloadLength, long limit) {
    long cost = (long) payloadLength + PER_FRAME;
    if (held.addAndGet(cost) > limit) {
      held.addAndGet(-cost);
      return -1;
    }
    return cost;
  }

  /** The frame counted by {@link #hold} was applied (or dropped). */
  public void release(long cost) {
    held.addAndGet(-cost);
  }

  /** Bytes held now (for tests). */
  public long held() {
    return held.get();
  }
}
