package dev.trade.examples.robot;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADELock;
import dev.trade.TRADELockedException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.PrintStream;
import java.time.Duration;
import java.util.List;
import java.util.Objects;

/**
 * A component that wants the head to look around (the TRADE paper's target-finding process): it
 * locks the head's {@code pan} and {@code tilt}; when another process holds them, it is told who,
 * waits for the lock, looks left and right, and releases the head. Not thread-safe: it runs once,
 * on one thread.
 */
public final class Lookout {
  private static final Duration WAIT = Duration.ofSeconds(20);

  private final TRADEContainer trade;
  private final String[] groups;
  private final PrintStream out;

  public Lookout(TRADEContainer trade, List<String> groups, PrintStream out) {
    this.trade = Objects.requireNonNull(trade, "trade == null");
    this.groups = groups.toArray(new String[0]);
    this.out = Objects.requireNonNull(out, "out == null");
  }

  /**
   * Looks around once it has the head.
   *
   * @return whether it did
   */
  public boolean run() {
    try {
      TRADEServiceInfo pan = trade.waitForService(need("pan"), WAIT);
      TRADEServiceInfo tilt = trade.waitForService(need("tilt"), WAIT);
      List<TRADEServiceInfo> head = List.of(pan, tilt);
      TRADELock lock;
      try {
        lock = trade.lock(head, Duration.ZERO);
      } catch (TRADELockedException busy) {
        out.println("the head is busy: " + busy.getMessage());
        out.println("waiting for the head");
        lock = trade.lock(head, WAIT);
      }
      try (TRADELock look = lock) {
        out.println("got the head: looking around");
        pan.call(look.getId(), double.class, 90.0);
        pan.call(look.getId(), double.class, -90.0);
        tilt.call(look.getId(), double.class, 0.0);
      }
      out.println("released the head");
      return true;
    } catch (TRADEException e) {
      out.println("lookout failed: " + e.getClass().getSimpleName() + ": " + e.getMessage());
      return false;
    }
  }

  private TRADEServiceConstraints need(String name) {
    return new TRADEServiceConstraints().name(name).argTypes(double.class).inGroups(groups);
  }
}
