package dev.trade.internal.net;

import dev.trade.internal.config.DiscoveryRange;
import dev.trade.internal.config.Settings;
import dev.trade.internal.discovery.Announcement;
import dev.trade.internal.discovery.Discovery;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * Turns multicast discovery into links: announces this container's listen addresses and, on
 * hearing a container of the same system it has no link to, connects to it. Of two containers that
 * hear each other, the one with the smaller id dials at once and the other only if no link appeared
 * shortly after, so that normally one connection is made, not two. Safe for concurrent use.
 */
final class Finder implements AutoCloseable {
  private static final Logger LOG = System.getLogger("dev.trade.discovery");
  private static final long SECOND_SIDE_DELAY_MS = 300;
  private static final long DIAL_GRACE_MS = 2_000;

  private final UUID self;
  private final Predicate<UUID> linked;
  private final Connector connector;
  private final ScheduledExecutorService timer;
  private final Discovery discovery;
  private final Map<UUID, Long> dialling = new ConcurrentHashMap<>();

  Finder(Settings settings, UUID self, String name, Supplier<List<InetSocketAddress>> listening,
      Predicate<UUID> linked, Connector connector, ScheduledExecutorService timer, boolean broadcast,
      boolean discover) throws IOException {
    this.self = self;
    this.linked = linked;
    this.connector = connector;
    this.timer = timer;
    this.discovery = Discovery.builder()
        .systemId(settings.tradeSysId())
        .credentials(settings.credentials())
        .group(settings.multicastAddress(), settings.broadcastPort())
        .interval(settings.broadcastInterval())
        .range(settings.discoveryRange() == DiscoveryRange.SUBNET
            ? Discovery.Range.SUBNET : Discovery.Range.LOCALHOST)
        .interfaces(settings.discoveryInterfaces())
        .container(self.toString(), name)
        .addresses(() -> concrete(listening.get()))
        .listener(this::heard)
        .broadcast(broadcast)
        .discovery(discover)
        .start();
  }

  void setBroadcast(boolean on) {
    discovery.setBroadcast(on);
  }

  void setDiscovery(boolean on) {
    discovery.setDiscovery(on);
  }

  boolean isBroadcasting() {
    return discovery.isBroadcasting();
  }

  boolean isDiscovering() {
    return discovery.isDiscovering();
  }

  /** Announces again now (the listen addresses changed). */
  void announceNow() {
    discovery.announceNow();
  }

  private void heard(Announcement a, InetAddress from) {
    UUID peer;
    try {
      peer = UUID.fromString(a.containerId());
    } catch (IllegalArgumentException e) {
      LOG.log(Level.DEBUG, "ignoring announcement with a foreign container id from {0}", from);
      return;
    }
    if (peer.equals(self) || linked.test(peer) || a.addresses().isEmpty()) {
      return;
    }
    long now = System.nanoTime();
    Long since = dialling.get(peer);
    if (since != null && now - since < TimeUnit.MILLISECONDS.toNanos(DIAL_GRACE_MS)) {
      return; // a dial is under way
    }
    dialling.put(peer, now);
    if (self.compareTo(peer) < 0) {
      dial(peer, a);
    } else {
      timer.schedule(() -> {
        if (!linked.test(peer)) {
          dial(peer, a);
        }
      }, SECOND_SIDE_DELAY_MS, TimeUnit.MILLISECONDS);
    }
  }

  private void dial(UUID peer, Announcement a) {
    LOG.log(Level.DEBUG, "heard {0} ({1}) at {2}; connecting", a.containerName(), peer, a.addresses());
    for (InetSocketAddress address : a.addresses()) {
      connector.connectOnce(address); // in parallel: the first to finish its handshake wins
    }
  }

  /** Wildcard listen addresses expanded to the addresses of every up interface. */
  private static List<InetSocketAddress> concrete(List<InetSocketAddress> listening) {
    List<InetSocketAddress> result = new ArrayList<>();
    for (InetSocketAddress a : listening) {
      if (!a.getAddress().isAnyLocalAddress()) {
        result.add(a);
        continue;
      }
      try {
        for (NetworkInterface nif : Collections.list(NetworkInterface.getNetworkInterfaces())) {
          if (nif.isUp()) {
            for (InetAddress ip : Collections.list(nif.getInetAddresses())) {
              if (!ip.isLinkLocalAddress() && ip.getClass() == a.getAddress().getClass()) {
                result.add(new InetSocketAddress(ip, a.getPort()));
              }
            }
          }
        }
      } catch (SocketException e) {
        LOG.log(Level.WARNING, "cannot list network interfaces: {0}", e.getMessage());
      }
    }
    return result;
  }

  @Override
  public void close() {
    discovery.close();
  }
}
