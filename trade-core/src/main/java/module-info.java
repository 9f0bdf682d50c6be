/**
 * TRADE: a service middleware for robot and agent architectures.
 *
 * <p>Only {@code dev.trade} is exported. Everything under {@code dev.trade.internal} is the
 * implementation (registry, call chain, codec, networking, discovery) and may change at any time.
 */
module dev.trade {
  // TRADE's tradeLogging.config files configure java.util.logging, the JDK's default backend of
  // System.Logger, through which TRADE logs.
  requires java.logging;

  exports dev.trade;
}
