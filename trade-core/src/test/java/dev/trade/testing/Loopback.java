package dev.trade.testing;

import java.net.InetAddress;
import java.net.InetSocketAddress;

/**
 * Addresses on the loopback interface, the only one tests use: a socket that picks a default
 * interface could send a packet off this machine.
 */
public final class Loopback {
  private Loopback() {}

  /** The loopback address. */
  public static final InetAddress ADDRESS = InetAddress.getLoopbackAddress();

  /** SERVERIPS for a container that listens on loopback, on a port the system picks. */
  public static final String ANY_PORT = "127.0.0.1@0";

  /** The loopback address with {@code port}. */
  public static InetSocketAddress address(int port) {
    return new InetSocketAddress(ADDRESS, port);
  }
}
