package dev.trade.internal.discovery;

import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ProtocolFamily;
import java.net.StandardProtocolFamily;
import java.net.StandardSocketOptions;
import java.nio.channels.DatagramChannel;
import java.util.List;

/**
 * Opens discovery's sockets, each with its interface named explicitly: a multicast socket left to
 * the routing table sends wherever the default route points, which is exactly the "discovery
 * works on my laptop but not on the robot" failure. Stateless.
 */
final class Sockets {
  private static final Logger LOG = System.getLogger(Discovery.class.getName());

  private Sockets() {}

  /**
   * A socket that receives the group's datagrams on {@code target}'s port, joined on each of
   * {@code interfaces}. It is bound to the group address where the OS allows it (Linux, macOS),
   * so that unicast datagrams to the port never reach it, otherwise to the wildcard address
   * (Windows); SO_REUSEADDR lets several containers on one host share the port.
   *
   * @throws IOException if the port cannot be bound, or the group cannot be joined on any interface
   */
  static DatagramChannel receiver(ProtocolFamily family, InetSocketAddress target,
      List<NetworkInterface> interfaces) throws IOException {
    DatagramChannel ch = DatagramChannel.open(family);
    try {
      ch.setOption(StandardSocketOptions.SO_REUSEADDR, true);
      try {
        ch.bind(target);
      } catch (IOException e) {
        LOG.log(Level.DEBUG, "Cannot bind to the group address ({0}); binding to the wildcard", e);
        try {
          ch.bind(new InetSocketAddress(target.getPort()));
        } catch (IOException again) {
          throw new IOException("Cannot bind the discovery port " + target.getPort() + ": "
              + again.getMessage() + "; does another program hold it without SO_REUSEADDR?", again);
        }
      }
      int joined = 0;
      IOException failure = null;
      for (NetworkInterface nif : interfaces) {
        try {
          ch.join(target.getAddress(), nif);
          joined++;
        } catch (IOException | UnsupportedOperationException e) {
          failure = new IOException("Cannot join " + target.getAddress().getHostAddress() + " on "
              + nif.getName() + ": " + e.getMessage(), e);
          LOG.log(Level.WARNING, failure.getMessage());
        }
      }
      if (joined == 0) {
        throw failure != null ? failure : new IOException("No interface to join the group on");
      }
      return ch;
    } catch (IOException | RuntimeException e) {
      closeQuietly(ch);
      throw e;
    }
  }

  /**
   * A socket that sends to the group on {@code nif} only, with the range's TTL, looping its
   * packets back to this host so that containers on the same machine hear each other. For
   * LOCALHOST it is also bound to the loopback address, so that it cannot send from anything else.
   * Other containers answer this container's announcements to it, unicast.
   */
  static DatagramChannel sender(ProtocolFamily family, NetworkInterface nif, Discovery.Range range)
      throws IOException {
    DatagramChannel ch = DatagramChannel.open(family);
    try {
      ch.setOption(StandardSocketOptions.IP_MULTICAST_IF, nif);
      ch.setOption(StandardSocketOptions.IP_MULTICAST_TTL, range.ttl);
      ch.setOption(StandardSocketOptions.IP_MULTICAST_LOOP, true);
      if (range == Discovery.Range.LOCALHOST) {
        ch.bind(new InetSocketAddress(family == StandardProtocolFamily.INET
            ? InetAddress.getByName("127.0.0.1") : InetAddress.getByName("::1"), 0));
      } else {
        ch.bind(null); // a port now, where answers from the others arrive
      }
      return ch;
    } catch (IOException | RuntimeException e) {
      closeQuietly(ch);
      throw e;
    }
  }

  static void closeQuietly(DatagramChannel ch) {
    try {
      ch.close();
    } catch (IOException e) {
      // Closing a datagram socket releases only local resources; nothing to report.
    }
  }
}
