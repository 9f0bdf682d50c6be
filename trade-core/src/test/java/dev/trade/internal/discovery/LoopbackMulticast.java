package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.StandardProtocolFamily;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.Collections;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.Assumptions;

/**
 * Multicast on the loopback interface for tests: a probe that tells whether it works here, free
 * ports, random groups, and a raw sender. Everything it sends goes out on loopback with TTL 0.
 *
 * <p>When the probe fails, tests fail with the reason if the environment variable {@code CI} is
 * {@code true}, and are skipped otherwise (a developer machine may lack loopback multicast; CI must
 * not silently skip the discovery tests).
 */
public final class LoopbackMulticast {
  private static String problem; // Guarded by the class; "" once the probe passed.

  private LoopbackMulticast() {}

  /** Skips (or, in CI, fails) the calling test unless multicast on loopback works. */
  public static synchronized void assumeUsable() {
    if (problem == null) {
      problem = probe();
    }
    if (problem.isEmpty()) {
      return;
    }
    String message = "IPv4 multicast on the loopback interface does not work here (" + problem
        + "). In a network namespace, run 'ip link set lo up' before the tests.";
    if ("true".equalsIgnoreCase(System.getenv("CI"))) {
      fail(message);
    }
    Assumptions.abort(message + " Skipping; CI=true would fail instead.");
  }

  static NetworkInterface loopback() throws IOException {
    for (NetworkInterface nif : Collections.list(NetworkInterface.getNetworkInterfaces())) {
      if (nif.isLoopback() && nif.isUp()) {
        return nif;
      }
    }
    throw new IOException("no loopback interface is up");
  }

  /** A UDP port that was free a moment ago. */
  static int freePort() throws IOException {
    try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
      return s.getLocalPort();
    }
  }

  /** A random administratively scoped IPv4 group, so that tests never hear each other. */
  static InetAddress randomGroup() throws IOException {
    ThreadLocalRandom r = ThreadLocalRandom.current();
    return InetAddress.getByAddress(new byte[] {(byte) 239, (byte) 255, (byte) r.nextInt(1, 255),
        (byte) r.nextInt(1, 255)});
  }

  /** A socket that can only send to groups on loopback, with TTL 0. */
  static DatagramChannel sender() throws IOException {
    DatagramChannel ch = DatagramChannel.open(StandardProtocolFamily.INET);
    ch.setOption(StandardSocketOptions.IP_MULTICAST_IF, loopback());
    ch.setOption(StandardSocketOptions.IP_MULTICAST_TTL, 0);
    ch.setOption(StandardSocketOptions.IP_MULTICAST_LOOP, true);
    ch.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
    return ch;
  }

  /** "" if a datagram sent to a group on loopback comes back within 2 s; otherwise why not. */
  private static String probe() {
    try {
      NetworkInterface lo = loopback();
      InetSocketAddress target = new InetSocketAddress(randomGroup(), freePort());
      try (DatagramChannel receiver = DatagramChannel.open(StandardProtocolFamily.INET);
          DatagramChannel sender = sender();
          Selector selector = Selector.open()) {
        receiver.setOption(StandardSocketOptions.SO_REUSEADDR, true);
        receiver.bind(new InetSocketAddress(target.getPort()));
        receiver.join(target.getAddress(), lo);
        receiver.configureBlocking(false);
        receiver.register(selector, SelectionKey.OP_READ);
        sender.send(ByteBuffer.wrap(new byte[] {1}), target);
        if (selector.select(2000) == 0) {
          return "a probe sent to " + target + " on " + lo.getName() + " did not arrive in 2 s";
        }
        return "";
      }
    } catch (IOException | RuntimeException e) {
      return e.toString();
    }
  }
}
