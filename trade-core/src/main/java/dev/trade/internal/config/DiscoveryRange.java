package dev.trade.internal.config;

import java.util.Locale;

/**
 * How far multicast discovery packets travel: the value of {@code DISCOVERYRANGE}.
 *
 * <p>The default stays on this machine so that two developers on one network never see each
 * other's containers by accident; reaching other machines is an explicit choice.
 */
public enum DiscoveryRange {
  /** Only this machine: the loopback interface, multicast TTL 0. */
  LOCALHOST(0),
  /**
   * The local subnet: TTL 1, on the interfaces named by {@code DISCOVERYINTERFACES}, or on every
   * interface that is up and supports multicast when none are named.
   */
  SUBNET(1);

  private final int ttl;

  DiscoveryRange(int ttl) {
    this.ttl = ttl;
  }

  /** The multicast time-to-live for discovery packets. */
  public int ttl() {
    return ttl;
  }

  /** The name as written in a settings file: {@code localhost} or {@code subnet}. */
  @Override
  public String toString() {
    return name().toLowerCase(Locale.ROOT);
  }
}
