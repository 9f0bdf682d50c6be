package dev.trade.examples.robot;

import dev.trade.TRADEService;

/** A mobile base that drives to named places. */
public interface Navigation {
  /**
   * Drives to {@code location} and returns when it is there.
   *
   * @return whether it arrived
   * @throws IllegalArgumentException for a place it does not know (the message lists the known
   *     ones)
   */
  @TRADEService
  boolean goTo(String location);
}
