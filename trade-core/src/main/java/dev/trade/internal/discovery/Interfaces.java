package dev.trade.internal.discovery;

import java.io.IOException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.InterfaceAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Which interfaces discovery uses, and which listen addresses it announces on each. Stateless.
 *
 * <p>Each interface's announcement lists only addresses that interface has, because an address
 * announced on a network that cannot reach it is the slowest way for discovery to fail: the peer
 * tries it and waits for a timeout. A wildcard listen address stands for every address of the
 * interface (of its family; the IPv6 wildcard also accepts IPv4 in the JDK's dual-stack sockets).
 */
final class Interfaces {
  private Interfaces() {}

  /**
   * The interfaces for {@code range}.
   *
   * <ul>
   *   <li>{@code LOCALHOST}: the loopback interface; {@code names} is ignored (as
   *       {@code DISCOVERYINTERFACES} is). Linux loopback often lacks the MULTICAST flag, so the
   *       JDK's {@code supportsMulticast()} says false; IPv4 multicast works on it anyway once
   *       {@code IP_MULTICAST_IF} names it, so that flag is not checked here.
   *   <li>{@code SUBNET}: the named interfaces, each of which must exist and be up; with no names,
   *       every interface that is up, supports multicast and is not loopback.
   * </ul>
   *
   * @throws IOException if no interface qualifies, or a named one does not exist or is down; the
   *     message lists the interfaces there are
   */
  static List<NetworkInterface> choose(Discovery.Range range, List<String> names)
      throws IOException {
    List<NetworkInterface> chosen = new ArrayList<>();
    if (range == Discovery.Range.LOCALHOST) {
      for (NetworkInterface nif : all()) {
        if (nif.isLoopback() && nif.isUp()) {
          chosen.add(nif);
          break;
        }
      }
      if (chosen.isEmpty()) {
        throw new IOException("No loopback interface is up, so range LOCALHOST cannot work;"
            + " interfaces: " + describeAll());
      }
      return List.copyOf(chosen);
    }
    if (!names.isEmpty()) {
      for (String name : new LinkedHashSet<>(names)) {
        NetworkInterface nif = NetworkInterface.getByName(name);
        if (nif == null || !nif.isUp()) {
          throw new IOException("Discovery interface '" + name + "' "
              + (nif == null ? "does not exist" : "is down") + "; interfaces: " + describeAll());
        }
        chosen.add(nif);
      }
      return List.copyOf(chosen);
    }
    for (NetworkInterface nif : all()) {
      if (nif.isUp() && nif.supportsMulticast() && !nif.isLoopback()) {
        chosen.add(nif);
      }
    }
    if (chosen.isEmpty()) {
      throw new IOException("No interface is up, multicast-capable and not loopback, so range"
          + " SUBNET has nothing to use; interfaces: " + describeAll()
          + ". Use range LOCALHOST, or name interfaces, or list peers in CONNECTCONTAINERS");
    }
    return List.copyOf(chosen);
  }

  /**
   * The addresses among {@code listen} to announce on {@code nif}, in order, without duplicates,
   * at most {@link Packets#MAX_ADDRESSES}; possibly empty.
   */
  static List<InetSocketAddress> announceable(NetworkInterface nif, List<InetSocketAddress> listen) {
    List<InetAddress> own = Collections.list(nif.getInetAddresses());
    Set<InetSocketAddress> result = new LinkedHashSet<>();
    for (InetSocketAddress l : listen) {
      if (l == null || l.isUnresolved() || l.getPort() == 0) {
        continue;
      }
      InetAddress a = l.getAddress();
      if (a.isAnyLocalAddress()) {
        boolean ipv4Only = a instanceof Inet4Address;
        for (InetAddress o : own) {
          if ((!ipv4Only || o instanceof Inet4Address) && Announcement.isAnnounceable(o)) {
            result.add(new InetSocketAddress(o, l.getPort()));
          }
        }
      } else if (Announcement.isAnnounceable(a) && isOn(a, own)) {
        result.add(l);
      }
    }
    List<InetSocketAddress> list = new ArrayList<>(result);
    return List.copyOf(list.subList(0, Math.min(list.size(), Packets.MAX_ADDRESSES)));
  }

  /**
   * {@code nif} as it is now: a {@link NetworkInterface} is a snapshot, and an address that DHCP
   * changed must not be announced from a stale one. The interface itself stays the one chosen at
   * start; if it is gone, the old snapshot is returned and sending on it fails visibly.
   */
  static NetworkInterface refresh(NetworkInterface nif) {
    try {
      NetworkInterface now = NetworkInterface.getByName(nif.getName());
      return now != null && now.getIndex() == nif.getIndex() ? now : nif;
    } catch (SocketException e) {
      return nif;
    }
  }

  /**
   * Whether {@code a} is on a network {@code nif} is attached to (within the prefix of one of its
   * addresses), so that a datagram to it leaves by {@code nif}: where an answer to a newcomer
   * heard on {@code nif} can go.
   */
  static boolean reaches(NetworkInterface nif, InetAddress a) {
    for (InterfaceAddress ia : nif.getInterfaceAddresses()) {
      InetAddress own = ia.getAddress();
      if (own.getClass() != a.getClass()) {
        continue;
      }
      if (own.isLoopbackAddress() && a.isLoopbackAddress()) {
        return true;
      }
      byte[] x = own.getAddress();
      byte[] y = a.getAddress();
      int bits = ia.getNetworkPrefixLength();
      boolean same = true;
      for (int i = 0; i < x.length && bits > 0 && same; i++, bits -= 8) {
        int mask = bits >= 8 ? 0xff : (0xff << (8 - bits)) & 0xff;
        same = (x[i] & mask) == (y[i] & mask);
      }
      if (same) {
        return true;
      }
    }
    return false;
  }

  private static boolean isOn(InetAddress a, List<InetAddress> own) {
    for (InetAddress o : own) {
      // All of 127.0.0.0/8 is on the loopback interface, though it lists only 127.0.0.1.
      if (a instanceof Inet4Address && a.isLoopbackAddress() && o instanceof Inet4Address
          && o.isLoopbackAddress()) {
        return true;
      }
      // Compare the bytes: an IPv6 address from the interface carries a scope, a configured one not.
      if (Arrays.equals(o.getAddress(), a.getAddress())) {
        return true;
      }
    }
    return false;
  }

  private static List<NetworkInterface> all() throws SocketException {
    return Collections.list(NetworkInterface.getNetworkInterfaces());
  }

  private static String describeAll() {
    try {
      List<String> out = new ArrayList<>();
      for (NetworkInterface nif : all()) {
        out.add(nif.getName() + (nif.isUp() ? "" : " (down)")
            + (nif.supportsMulticast() ? "" : " (no multicast)")
            + (nif.isLoopback() ? " (loopback)" : ""));
      }
      return String.join(", ", out);
    } catch (SocketException e) {
      return "(cannot list: " + e.getMessage() + ")";
    }
  }
}
