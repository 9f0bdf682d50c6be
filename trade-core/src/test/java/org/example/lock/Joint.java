package org.example.lock;

import dev.trade.TRADEService;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * An effector to lock: it counts the moments when two callers were inside it at once, which a lock
 * held by one of them must make impossible.
 */
public final class Joint {
  private final AtomicReference<String> inside = new AtomicReference<>();
  final AtomicInteger overlaps = new AtomicInteger();
  final AtomicInteger moves = new AtomicInteger();

  @TRADEService
  public int move(int degrees) {
    moves.incrementAndGet();
    return degrees;
  }

  @TRADEService
  public void enter(String who) {
    if (!inside.compareAndSet(null, who)) {
      overlaps.incrementAndGet();
    }
  }

  @TRADEService
  public void leave(String who) {
    if (!inside.compareAndSet(who, null)) {
      overlaps.incrementAndGet();
    }
  }
}
