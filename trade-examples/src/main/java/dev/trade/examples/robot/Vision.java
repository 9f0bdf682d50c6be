package dev.trade.examples.robot;

import dev.trade.TRADEService;

/** A camera component that can look for objects (the TRADE paper's {@code checkFor}). */
public interface Vision {
  /**
   * Looks for an object of the given type in the current view.
   *
   * @return where it is, or {@link Detection#none(String)}; never null
   */
  @TRADEService
  Detection checkFor(String objectType);
}
