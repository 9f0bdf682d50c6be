package dev.trade.internal.net.join;

import dev.trade.internal.config.DiscoveryRange;
import dev.trade.internal.config.PeerAddress;
import dev.trade.internal.config.Settings;
import dev.trade.internal.net.link.Connector;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ScheduledExecutorService;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * How a container is found: the sockets it accepts connections on and the {@link Finder} that
 * announces them and hears other containers, with the switches that turn announcing and
 * discovery on or off at run time. The finder is made when first needed, never once the
 * container has closed.
 *
 * <p>Safe for concurrent use: listening and the finder are set up, switched and closed under
 * this object's lock.
 */
public final class DiscoveryController implements AutoCloseable {
  private final Settings settings;
  private final UUID self;
  private final String name;
  private final Connector connector;
  private final Predicate<UUID> linked;
  private final Supplier<Set<UUID>> reachable;
  private final ScheduledExecutorService timer;
  private final BooleanSupplier closed;
  // Guarded by this.
  private Finder finder;

  /**
   * @param linked whether this container has a link to a container, or a handshake with it under
   *     way (then it is not dialled)
   * @param reachable the other containers routing reaches now
   * @param closed whether the container has closed (then no finder is made any more)
   */
  public DiscoveryController(Settings settings, UUID self, String name, Connector connector,
      Predicate<UUID> linked, Supplier<Set<UUID>> reachable, ScheduledExecutorService timer,
      BooleanSupplier closed) {
    this.settings = settings;
    this.self = self;
    this.name = name;
    this.connector = connector;
    this.linked = linked;
    this.reachable = reachable;
    this.timer = timer;
    this.closed = closed;
  }

  /**
   * Listens on SERVERIPS, or where discovery can reach: loopback for the {@code localhost} range,
   * every interface for {@code subnet} (announced per interface, never as a wildcard).
   */
  public synchronized void listen() throws IOException {
    if (!connector.listening().isEmpty()) {
      return;
    }
    List<PeerAddress> listen = settings.serverAddresses();
    if (listen.isEmpty()) {
      listen = List.of(new PeerAddress(
          settings.discoveryRange() == DiscoveryRange.SUBNET ? "0.0.0.0" : "127.0.0.1", 0));
    }
    for (PeerAddress a : listen) {
      try {
        connector.listen(new InetSocketAddress(a.host(), a.port()));
      } catch (IOException e) {
        throw new IOException("cannot listen on SERVERIPS address " + a + ": " + e.getMessage(), e);
      }
    }
  }

  /** A container left or died (routing lost it): discovery stops counting it at once. */
  public void unreachable(UUID container) {
    if (closed.getAsBoolean()) {
      return;
    }
    Finder f;
    synchronized (this) {
      f = finder;
    }
    if (f != null) {
      f.forget(container);
    }
  }

  /** The finder, made with these switches if there is none yet; null once the container closed. */
  public synchronized Finder finder(boolean broadcast, boolean discover) throws IOException {
    if (finder == null && !closed.getAsBoolean()) {
      finder = new Finder(settings, self, name, connector::announceable, linked, reachable,
          connector, timer, broadcast, discover);
    }
    return finder;
  }

  /**
   * Turns multicast discovery (listening for announcements and connecting) on or off at run time.
   *
   * @throws IOException if discovery has to start and cannot open its socket
   */
  public void setDiscovery(boolean on) throws IOException {
    Finder f = finder(false, on);
    if (f != null) {
      f.setDiscovery(on);
    }
  }

  /**
   * Turns announcing this container on or off at run time (it then accepts connections, if it did
   * not already).
   *
   * @throws IOException if a listen socket or the discovery socket cannot be opened
   */
  public void setBroadcast(boolean on) throws IOException {
    if (on) {
      listen();
    }
    Finder f = finder(on, false);
    if (f != null) {
      f.setBroadcast(on);
      if (on) {
        f.announceNow();
      }
    }
  }

  /** Whether this container listens for announcements. */
  public synchronized boolean isDiscovering() {
    return finder != null && finder.isDiscovering();
  }

  /** Whether this container announces itself. */
  public synchronized boolean isBroadcasting() {
    return finder != null && finder.isBroadcasting();
  }

  /** Closes the finder, if there is one (the container closes). */
  @Override
  public synchronized void close() {
    if (finder != null) {
      finder.close();
    }
  }
}
