package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ProtocolFamily;
import java.net.StandardProtocolFamily;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ScheduledExecutorService;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * Finds the other containers of a system by UDP multicast, and tells them about this one.
 *
 * <p>Announcing: an {@link Announcement} of this container's listen addresses goes to the group on
 * each chosen interface in a quick burst at start (0, 20, 50, 100 and 200 ms), then every
 * interval, and once more on {@link #announceNow()}. The first announcement heard from a container
 * is answered straight to the socket it came from (so that a newcomer learns about the others in
 * milliseconds too, and the others do not hear every answer). Each interface's packet lists only that
 * interface's addresses, never a wildcard; an interface with none gets no packet, so a container
 * without listen addresses listens but announces nothing.
 *
 * <p>Listening: a daemon thread receives from the group, and answers on the sending sockets. A packet that fails a check is dropped,
 * counted by {@link Reason} ({@link #dropCounts()}) and logged at DEBUG, with a rate-limited INFO
 * or WARNING that says why ("other system id 'x'", "bad HMAC: wrong CREDENTIALS?"). Every other
 * announcement goes to the {@link Listener}, on that thread.
 *
 * <p>{@link Range#LOCALHOST}: the loopback interface only, TTL 0, so nothing leaves the machine.
 * {@link Range#SUBNET}: TTL 1 on each chosen interface. Every socket names its interface.
 *
 * <pre>{@code
 * Discovery d = Discovery.builder()
 *     .systemId("diarc").credentials(secret)
 *     .group(InetAddress.getByName("230.1.1.1"), 33333)
 *     .container(id, name)
 *     .addresses(server::listenAddresses)
 *     .listener((a, from, answer) -> connector.offer(a))   // hands off; never blocks
 *     .start();
 * }</pre>
 *
 * <p>This class is safe for concurrent use.
 */
public final class Discovery implements AutoCloseable {
  /** How far announcements travel. */
  public enum Range {
    /** Only this machine: the loopback interface, multicast TTL 0. */
    LOCALHOST(0),
    /** The networks of the chosen interfaces: multicast TTL 1. */
    SUBNET(1);

    final int ttl;

    Range(int ttl) {
      this.ttl = ttl;
    }
  }

  /** Told of each announcement that passed every check. */
  @FunctionalInterface
  public interface Listener {
    /**
     * Called on the discovery's scheduler (see {@link Builder#scheduler}), one announcement at a
     * time. Return quickly: while it runs, this container's further datagrams wait (beyond
     * {@value Receiver#MAX_WAITING} they are dropped), though other containers' in the JVM do
     * not. Called for every accepted announcement, also the periodic repeats of a known
     * container. An exception is logged and does not stop discovery.
     *
     * @param from the datagram's source address, for logs; connect to {@code a.addresses()}
     * @param answer whether it came straight to this container, in answer to this container's own
     *     announcement (see {@link Builder#answering}), rather than to the group
     */
    void heard(Announcement a, InetAddress from, boolean answer);
  }

  private static final Logger LOG = System.getLogger(Discovery.class.getName());

  private final List<NetworkInterface> interfaces;
  private final Announcer announcer;
  private final Receiver receiver;
  private final Object lock = new Object();
  private boolean closed; // Guarded by lock.

  private Discovery(Builder b) throws IOException {
    byte[] key = Packets.deriveKey(b.systemId, b.credentials);
    InetSocketAddress target = new InetSocketAddress(b.group, b.port);
    this.interfaces = Interfaces.choose(b.range, b.interfaces);
    ProtocolFamily family = b.group instanceof Inet4Address
        ? StandardProtocolFamily.INET : StandardProtocolFamily.INET6;
    List<DatagramChannel> senders = new ArrayList<>();
    try {
      for (NetworkInterface nif : interfaces) {
        senders.add(Sockets.sender(family, nif, b.range));
      }
    } catch (IOException | RuntimeException e) {
      senders.forEach(Sockets::closeQuietly);
      throw e;
    }
    String tag = "[" + b.containerName + "]";
    this.announcer = new Announcer(b.systemId, b.containerId, b.containerName, key, target,
        b.addresses, interfaces, senders, b.broadcast, b.scheduler, "trade-discovery" + tag);
    // Received datagrams are handled where announcements are sent: the container's timer.
    this.receiver = new Receiver(senders, b.systemId, b.containerId, key, b.listener,
        (a, from) -> {
          if (b.answering.test(a.containerId())) {
            announcer.answer(from);
          }
        }, b.observer, replayGuard(b), b.reportInterval, b.discovery, announcer.executor());
    try {
      receiver.start(family, target, interfaces);
    } catch (IOException | RuntimeException e) {
      announcer.close(); // and the senders
      throw e;
    }
    // The start line waits, with the interfaces' first lines, until the start burst has been sent
    // (Announcer). The TTL goes in as text: a number makes the logger set up the locale's number
    // format first.
    Object[] facts = {b.containerName, b.systemId, Announcement.format(target), interfaceNames(),
        b.range, Integer.toString(b.range.ttl), b.broadcast, b.discovery};
    announcer.start(b.interval, () -> LOG.log(Level.INFO, "Discovery of ''{0}'' in system ''{1}''"
        + " on {2} via {3} ({4}, TTL {5}): announcing {6}, listening {7}", facts));
  }

  /**
   * The receiver's replay guard: it keeps a sender for three announcement intervals at least, so
   * that with announcements further apart than the clock tolerance, a container that keeps
   * announcing is not taken for a newcomer (and answered) each time.
   */
  static ReplayGuard replayGuard(Builder b) {
    return new ReplayGuard(ReplayGuard.DEFAULT_MAX_SENDERS, b.maxClockSkew,
        b.interval.multipliedBy(3));
  }

  /** A builder; see {@link Builder} for what is required and the defaults. */
  public static Builder builder() {
    return new Builder();
  }

  /**
   * Turns announcing on or off. Turning it on sends a burst, as at start. Once this has returned
   * after turning it off, no further packet is sent.
   */
  public void setBroadcast(boolean on) {
    announcer.setOn(on);
  }

  public boolean isBroadcasting() {
    return announcer.isOn();
  }

  /**
   * Turns listening on or off. While off, datagrams are still read (so that stale ones do not
   * wait in the kernel's buffer) but discarded unchecked and uncounted, and the listener is not
   * called; a call already in progress may finish after this returns.
   */
  public void setDiscovery(boolean on) {
    receiver.setOn(on);
  }

  public boolean isDiscovering() {
    return receiver.isOn();
  }

  /**
   * Announces once, soon, on the sending thread; call it when the listen addresses change. Does
   * nothing while announcing is off or after {@link #close()}.
   */
  public void announceNow() {
    announcer.announceNow();
  }

  /** How many packets were dropped, by reason, with every reason present. An unmodifiable snapshot. */
  public Map<Reason, Long> dropCounts() {
    return receiver.dropCounts();
  }

  /** The names of the interfaces in use, for logs and diagnostics. */
  public List<String> interfaceNames() {
    List<String> names = new ArrayList<>();
    interfaces.forEach(nif -> names.add(nif.getName()));
    return names;
  }

  /** Packets sent so far (for tests). */
  long sentCount() {
    return announcer.sentCount();
  }

  /** Datagrams discarded while listening was off (for tests). */
  long ignoredCount() {
    return receiver.ignoredCount();
  }

  /**
   * Stops announcing and listening and closes the sockets; idempotent. When it returns, no packet
   * is sent any more and the listener is no longer called, unless close is called from the
   * listener or the listener has been blocked for more than 2 s (which is logged).
   */
  @Override
  public void close() {
    synchronized (lock) {
      if (closed) {
        return;
      }
      closed = true;
    }
    announcer.close();
    receiver.close();
  }

  /**
   * Collects the settings of a {@link Discovery}. Required: {@link #systemId}, {@link #group},
   * {@link #container} and {@link #listener}. Not thread-safe; use it on one thread.
   */
  public static final class Builder {
    private String systemId;
    private String credentials = "";
    private InetAddress group;
    private int port;
    private Duration interval = Duration.ofSeconds(3);
    private Range range = Range.LOCALHOST;
    private List<String> interfaces = List.of();
    private String containerId;
    private String containerName;
    private Supplier<List<InetSocketAddress>> addresses = List::of;
    private Listener listener;
    private boolean broadcast = true;
    private boolean discovery = true;
    private Duration maxClockSkew = ReplayGuard.DEFAULT_MAX_CLOCK_SKEW;
    private Duration reportInterval = Duration.ofSeconds(60);
    private Receiver.Observer observer = Receiver.Observer.NONE;
    private ScheduledExecutorService scheduler;
    private Predicate<String> answering = newcomer -> true;

    private Builder() {}

    /** {@code TRADESYSID}: 1 to 64 bytes of UTF-8 without control characters. */
    public Builder systemId(String systemId) {
      Announcement.checkText(systemId, "system id", Packets.MAX_SYSTEM_ID);
      this.systemId = systemId;
      return this;
    }

    /** {@code CREDENTIALS}, the HMAC secret; default empty (no protection against forgery). */
    public Builder credentials(String credentials) {
      this.credentials = Objects.requireNonNull(credentials, "credentials == null");
      return this;
    }

    /** {@code MCAST_ADDR} and {@code BROADCASTPORT}. */
    public Builder group(InetAddress group, int port) {
      Objects.requireNonNull(group, "group == null");
      if (!group.isMulticastAddress()) {
        throw new IllegalArgumentException(group.getHostAddress() + " is not a multicast address");
      }
      if (port < 1 || port > 65535) {
        throw new IllegalArgumentException("port " + port + " is not in 1..65535");
      }
      this.group = group;
      this.port = port;
      return this;
    }

    /** {@code BROADCASTINTERVAL}: the steady time between announcements; default 3 s. */
    public Builder interval(Duration interval) {
      if (interval.toMillis() < 1) {
        throw new IllegalArgumentException("interval " + interval + " is under 1 ms");
      }
      this.interval = interval;
      return this;
    }

    /** How far announcements travel; default {@link Range#LOCALHOST}. */
    public Builder range(Range range) {
      this.range = Objects.requireNonNull(range, "range == null");
      return this;
    }

    /**
     * {@code DISCOVERYINTERFACES}: interface names for {@link Range#SUBNET}; empty (the default)
     * means every interface that is up, multicast-capable and not loopback. Ignored for
     * {@link Range#LOCALHOST}, which always uses the loopback interface.
     */
    public Builder interfaces(List<String> names) {
      this.interfaces = List.copyOf(names);
      return this;
    }

    /** This container's id (unique per incarnation) and name, as announced. */
    public Builder container(String id, String name) {
      Announcement.checkText(id, "container id", Packets.MAX_CONTAINER_ID);
      Announcement.checkText(name, "container name", Packets.MAX_CONTAINER_NAME);
      this.containerId = id;
      this.containerName = name;
      return this;
    }

    /**
     * Where this container accepts connections, asked on the sending thread at most once a second
     * and after {@link Discovery#announceNow()}: it must not block. Wildcard addresses stand for
     * each interface's own; an empty list (the default) means nothing is announced.
     */
    public Builder addresses(Supplier<List<InetSocketAddress>> addresses) {
      this.addresses = Objects.requireNonNull(addresses, "addresses == null");
      return this;
    }

    /** Told of every accepted announcement; see {@link Listener#heard} for its contract. */
    public Builder listener(Listener listener) {
      this.listener = Objects.requireNonNull(listener, "listener == null");
      return this;
    }

    /** {@code STARTBROADCAST}: whether to announce from the start; default true. */
    public Builder broadcast(boolean on) {
      this.broadcast = on;
      return this;
    }

    /** {@code STARTDISCOVERY}: whether to listen from the start; default true. */
    public Builder discovery(boolean on) {
      this.discovery = on;
      return this;
    }

    /**
     * How far a sender's clock may be from ours, either way; default 30 s. Zero turns the check
     * off (see {@link ReplayGuard}).
     */
    public Builder maxClockSkew(Duration tolerance) {
      if (tolerance.isNegative()) {
        throw new IllegalArgumentException("clock skew tolerance " + tolerance + " is negative");
      }
      this.maxClockSkew = tolerance;
      return this;
    }

    /** The least time between two INFO/WARNING reports of one drop reason from one address. */
    Builder reportInterval(Duration interval) {
      this.reportInterval = Objects.requireNonNull(interval, "interval == null");
      return this;
    }

    /**
     * Sends announcements, and handles the datagrams received, on {@code scheduler} instead of a
     * thread of discovery's own; its tasks must be short (each send is). {@link Discovery#close()}
     * ends discovery's tasks on it but does not shut it down. Default: a daemon thread of its own.
     */
    public Builder scheduler(ScheduledExecutorService scheduler) {
      this.scheduler = Objects.requireNonNull(scheduler, "scheduler == null");
      return this;
    }

    /**
     * Which newcomers, by container id, this container answers at their first announcement, so
     * that they learn of it at once rather than at its next announcement to the group. Asked on
     * the scheduler, like the listener: it must be quick. Default: every one.
     */
    public Builder answering(Predicate<String> newcomer) {
      this.answering = Objects.requireNonNull(newcomer, "newcomer == null");
      return this;
    }

    /** Sees every drop and every datagram ignored while listening is off (for tests). */
    Builder observer(Receiver.Observer observer) {
      this.observer = Objects.requireNonNull(observer, "observer == null");
      return this;
    }

    /**
     * Opens the sockets and starts announcing and listening as configured.
     *
     * @throws IllegalStateException if a required setting is missing
     * @throws IOException if the port cannot be bound, the group cannot be joined, or no interface
     *     fits the range; the message says which and lists the interfaces there are
     */
    public Discovery start() throws IOException {
      if (systemId == null || group == null || containerId == null || listener == null) {
        throw new IllegalStateException("Discovery needs systemId, group, container and listener");
      }
      return new Discovery(this);
    }
  }
}
