package dev.trade.examples.robot;

import dev.trade.TRADEService;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A simulated battery gauge that drains by one percent each time it is read. Safe for concurrent
 * use.
 */
public final class BatteryMonitor {
  private static final int LOW = 20;

  private final AtomicInteger level;

  /** A battery charged to {@code percent} (0..100). */
  public BatteryMonitor(int percent) {
    if (percent < 0 || percent > 100) {
      throw new IllegalArgumentException("percent must be 0..100: " + percent);
    }
    this.level = new AtomicInteger(percent);
  }

  /** The charge left, in percent. */
  @TRADEService
  public int level() {
    return level.getAndUpdate(l -> Math.max(0, l - 1));
  }

  /** Whether the robot should go back to its dock. */
  @TRADEService
  public boolean isLow() {
    return level.get() < LOW;
  }
}
