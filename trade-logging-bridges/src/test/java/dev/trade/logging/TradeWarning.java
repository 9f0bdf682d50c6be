package dev.trade.logging;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;

/** Makes TRADE log one WARNING through System.Logger, whichever backend receives it. */
final class TradeWarning {
  /** The start of its text. */
  static final String TEXT = "registered a java.lang.Object in container bridged with no services";

  private TradeWarning() {}

  /** Registers an object without services, which logs on {@code dev.trade.registry}. */
  static void log() {
    try (TRADEContainer c = TRADEContainer.builder().name("bridged").build()) {
      c.registerAllServices(new Object());
    } catch (TRADEException e) {
      throw new AssertionError(e);
    }
  }
}
