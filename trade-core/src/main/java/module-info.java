/**
 * TRADE: a service middleware for robot and agent architectures.
 *
 * <p>Only {@code dev.trade} is exported. Everything under {@code dev.trade.internal} is the
 * implementation (registry, call chain, codec, networking, discovery) and may change at any time.
 */
module dev.trade {
  exports dev.trade;
}
