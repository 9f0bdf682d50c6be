package org.example.lock;

import dev.trade.TRADEService;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * An effector to lock: it counts the moments when two callers were inside it at once, which a lock
 * held by one of them must make impossible.
 */
public final class Joint {
  private String inside; // Guarded by this.
  final AtomicInteger overlaps = new AtomicInteger();
  final AtomicInteger moves = new AtomicInteger();

  @TRADEService
  public int move(int degrees) {
    moves.incrementAndGet();
    return degrees;
  }

  @TRADEService
  public synchronized void enter(String who) {
    if (inside != null) {
      overlaps.incrementAndGet();
    }
    inside = who;
  }

  @TRADEService
  public synchronized void leave(String who) {
    if (!who.equals(inside)) {
      overlaps.incrementAndGet();
    }
    inside = null;
  }
}
