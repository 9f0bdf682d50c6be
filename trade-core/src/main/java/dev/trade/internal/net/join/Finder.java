package dev.trade.internal.net.join;

import dev.trade.internal.config.DiscoveryRange;
import dev.trade.internal.config.PeerAddress;
import dev.trade.internal.config.Settings;
import dev.trade.internal.discovery.Announcement;
import dev.trade.internal.discovery.Discovery;
import dev.trade.internal.net.link.Connector;
import dev.trade.internal.net.link.LinkReferee;
import dev.trade.internal.time.Scheduler;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import java.util.function.Supplier;

/**
 * How a container is found and whom it links to: the sockets it accepts connections on, the
 * switches that turn announcing and discovery on or off at run time, and the finding itself. It
 * announces this container's listen addresses, keeps the
 * set of live containers it hears, and dials the ones {@link Overlay} chooses out of that set
 * (all of them in a small system, O(log n) in a large one; the rest are reached by forwarding).
 * A newcomer first dials the overlay's choice out of those that answered it, then, once it has
 * heard enough of the system, out of all (see {@link #holding}). A container stays known until it
 * has not announced itself for three intervals, or until routing finds it unreachable
 * ({@link #forget}). Links that exist are never closed here, whoever made them.
 *
 * <p>Of two containers that choose each other, the one with the smaller id dials at once and the
 * other only if no link appeared shortly after, so that normally one connection is made, not two;
 * a container that only one side chooses is dialled at once.
 *
 * <p>Multicast discovery ({@code dev.trade.internal.discovery}) starts when first switched on,
 * never once the container has closed. Safe for concurrent use: listening and discovery are set
 * up, switched and closed under {@code switches}; choosing is guarded by this object's lock.
 */
public final class Finder implements AutoCloseable {
  private static final Logger LOG = System.getLogger("dev.trade.discovery");
  private static final long SECOND_SIDE_DELAY_MS = 300;
  private static final long DIAL_GRACE_MS = 2_000;
  private static final long SWEEP_MS = 1_000;
  private static final long SETTLE_MS = 100;
  /**
   * The longest a newcomer waits to hear the containers routing reaches before it chooses, in
   * announcement intervals (see {@link #holding}): each one within discovery's reach announces
   * itself once an interval, so one interval hears them all, and the second is slack for a busy
   * machine.
   */
  static final int HOLD_MAX_INTERVALS = 2;
  /** How long a forgotten container's old announcements are ignored (the replay guard's window). */
  private static final long FORGET_NANOS = TimeUnit.SECONDS.toNanos(60);

  /** A container heard: its latest announcement, and when that arrived (nanoTime). */
  private record Heard(Announcement announcement, long atNanos) {}

  private final Settings settings;
  private final UUID self;
  /** This container's name, for the DEBUG lines that trace a join. */
  private final String name;
  private final Predicate<UUID> linked;
  private final Supplier<Set<UUID>> reachable;
  private final Connector connector;
  private final Scheduler scheduler;
  private final BooleanSupplier closed;
  private final Object switches = new Object();
  /** Multicast discovery, once switched on; null before. Written under switches. */
  private volatile Discovery discovery;
  private ScheduledFuture<?> sweep; // Guarded by switches.
  private final long expiry;
  private final long holdMax;
  private final Map<UUID, Long> dialling = new ConcurrentHashMap<>();
  private final Map<UUID, Heard> known = new ConcurrentHashMap<>();
  /** Containers that left: the last announcement sequence seen and when (nanoTime). */
  private final Map<UUID, long[]> forgotten = new ConcurrentHashMap<>();
  private final AtomicBoolean choosing = new AtomicBoolean();
  private volatile Set<UUID> wanted = Set.of();
  /** The containers that answered this one's announcements (see {@link #early}). */
  private final Set<UUID> answered = ConcurrentHashMap.newKeySet();
  /** When the first choice was made (nanoTime), 0 before it. Guarded by this. */
  private long firstChoiceAt;

  /**
   * Finds nothing yet: listening starts with {@link #listen}, discovery with {@link #start} or a
   * switch.
   *
   * @param linked whether this container has a link to a container, or a handshake with it under
   *     way (then it is not dialled)
   * @param reachable the other containers routing reaches now
   * @param scheduler the container's clock and timer
   * @param closed whether the container has closed (then discovery does not start any more)
   */
  public Finder(Settings settings, UUID self, String name, Connector connector,
      Predicate<UUID> linked, Supplier<Set<UUID>> reachable, Scheduler scheduler,
      BooleanSupplier closed) {
    this.settings = settings;
    this.self = self;
    this.name = name;
    this.linked = linked;
    this.reachable = reachable;
    this.connector = connector;
    this.scheduler = scheduler;
    this.closed = closed;
    this.expiry = 3 * settings.broadcastInterval().toNanos() + TimeUnit.MILLISECONDS.toNanos(SWEEP_MS);
    this.holdMax = HOLD_MAX_INTERVALS * settings.broadcastInterval().toNanos();
  }

  /**
   * Listens on SERVERIPS, or where discovery can reach: loopback for the {@code localhost} range,
   * every interface for {@code subnet} (announced per interface, never as a wildcard).
   */
  public void listen() throws IOException {
    synchronized (switches) {
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
          throw new IOException("cannot listen on SERVERIPS address " + a + ": " + e.getMessage(),
              e);
        }
      }
    }
  }

  /**
   * Starts multicast discovery with these switches if it has not started; nothing once the
   * container closed.
   *
   * @return whether discovery runs
   * @throws IOException if the discovery socket cannot be opened
   */
  public boolean start(boolean broadcast, boolean discover) throws IOException {
    synchronized (switches) {
      if (discovery == null && !closed.getAsBoolean()) {
        discovery = Discovery.builder()
            .systemId(settings.tradeSysId())
            .credentials(settings.credentials())
            .group(settings.multicastAddress(), settings.broadcastPort())
            .interval(settings.broadcastInterval())
            .range(settings.discoveryRange() == DiscoveryRange.SUBNET
                ? Discovery.Range.SUBNET : Discovery.Range.LOCALHOST)
            .interfaces(settings.discoveryInterfaces())
            .maxClockSkew(settings.discoveryClockSkew())
            .container(self.toString(), name)
            .addresses(connector::announceable)
            .listener(this::heard)
            .answering(this::answers)
            .broadcast(broadcast)
            .discovery(discover)
            .scheduler(scheduler.timer())
            .start();
        sweep = scheduler.timer().scheduleWithFixedDelay(() -> sweep(scheduler.nanoTime()),
            SWEEP_MS, SWEEP_MS, TimeUnit.MILLISECONDS);
      }
      return discovery != null;
    }
  }

  /**
   * Turns multicast discovery (listening for announcements and connecting) on or off at run time.
   *
   * @throws IOException if discovery has to start and cannot open its socket
   */
  public void setDiscovery(boolean on) throws IOException {
    if (start(false, on)) {
      discovery.setDiscovery(on);
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
    if (start(on, false)) {
      discovery.setBroadcast(on);
      if (on) {
        discovery.announceNow();
      }
    }
  }

  /** Whether this container listens for announcements. */
  public boolean isDiscovering() {
    Discovery d = discovery;
    return d != null && d.isDiscovering();
  }

  /** Whether this container announces itself. */
  public boolean isBroadcasting() {
    Discovery d = discovery;
    return d != null && d.isBroadcasting();
  }

  /**
   * Forgets {@code peer} (routing found it unreachable: it left or died), so that the overlay forms
   * again without it at once; its announcements count again only when newer than the last one
   * heard. Any thread; nothing once the container closed.
   */
  public void unreachable(UUID peer) {
    if (!closed.getAsBoolean() && discovery != null) {
      forget(peer);
    }
  }

  /** See {@link #unreachable}. */
  private void forget(UUID peer) {
    answered.remove(peer);
    Heard h = known.remove(peer);
    if (h != null) {
      forgotten.put(peer, new long[] {h.announcement().sequence(), scheduler.nanoTime()});
      membershipChanged();
    }
  }

  /** The containers this one currently chooses to dial (for tests and logs). */
  Set<UUID> wanted() {
    return wanted;
  }

  private void heard(Announcement a, InetAddress from, boolean answer) {
    UUID peer;
    try {
      peer = UUID.fromString(a.containerId());
    } catch (IllegalArgumentException e) {
      LOG.log(Level.DEBUG, "ignoring announcement with a foreign container id from {0}", from);
      return;
    }
    if (peer.equals(self) || a.addresses().isEmpty()) {
      return;
    }
    long[] gone = forgotten.get(peer);
    if (gone != null) {
      if (a.sequence() <= gone[0]) {
        return; // sent before it left, and delivered late
      }
      forgotten.remove(peer);
    }
    if (answer) {
      answered.add(peer);
    }
    if (known.put(peer, new Heard(a, scheduler.nanoTime())) == null) {
      LOG.log(Level.DEBUG, "{0}: heard {1} ({2})", name, a.containerName(), peer);
      membershipChanged();
    } else if (wanted.contains(peer)) {
      consider(peer);
    }
  }

  /**
   * Whether to answer {@code newcomer}'s first announcement (see {@link Discovery.Builder#answering}):
   * when its overlay, knowing the containers this one knows, would dial this container, and always
   * in a fully meshed system. A newcomer dials only those; answered by every container, a newcomer
   * to a system of 100 drew 99 answers, each signed, sent, received and checked, and each woke a
   * thread in the JVM that sent it. It hears the others at their next announcement to the group.
   * Runs on the receiving thread.
   */
  private boolean answers(String newcomer) {
    UUID peer;
    try {
      peer = UUID.fromString(newcomer);
    } catch (IllegalArgumentException e) {
      return true; // not one of ours to reason about: answer as discovery always did
    }
    return answers(self, peer, known.keySet());
  }

  /**
   * The rule of {@link #answers(String)}: whether {@code self}, knowing {@code known} (itself not
   * among them), answers.
   */
  static boolean answers(UUID self, UUID newcomer, Collection<UUID> known) {
    int members = known.size() + 1 + (known.contains(newcomer) ? 0 : 1);
    if (members <= Overlay.FULL_MESH_MAX) {
      return true;
    }
    // The overlay puts the members in a set of its own (the newcomer, its chooser, among them).
    List<UUID> withSelf = new ArrayList<>(members);
    withSelf.addAll(known);
    withSelf.add(self);
    return Overlay.chooses(newcomer, self, withSelf);
  }

  /**
   * Chooses again {@link #SETTLE_MS} after the first change, with every change heard until then: a
   * newcomer hears the answers of the containers it will dial within milliseconds, and choosing at
   * the first one would mesh it with whoever answered first, links that then stay. The first container
   * heard at all is chosen at once, so that two containers on their own link without delay.
   */
  private void membershipChanged() {
    if (known.size() == 1) {
      choose();
    } else if (choosing.compareAndSet(false, true)) {
      later(this::choose, SETTLE_MS);
    }
  }

  private synchronized void choose() {
    choosing.set(false);
    if (holding()) {
      Set<UUID> early = early(self, answered, known.keySet(), linkedNow());
      if (!early.isEmpty()) {
        boolean changed = !early.equals(wanted);
        wanted = early;
        early.forEach(this::consider);
        if (changed && LOG.isLoggable(Level.DEBUG)) { // after its dials, as below
          LOG.log(Level.DEBUG, "{0}: holding, chose {1} of the {2} that answered", name,
              new TreeSet<>(early), answered.size());
        }
      }
      if (choosing.compareAndSet(false, true)) {
        later(this::choose, SETTLE_MS); // look again then
      }
      return;
    }
    Set<UUID> now = Set.copyOf(Overlay.chosen(self, known.keySet(), linkedNow()));
    wanted = now;
    for (UUID peer : now) {
      consider(peer);
    }
    if (LOG.isLoggable(Level.DEBUG)) { // after the dials made at once: a trace shows them first
      LOG.log(Level.DEBUG, "{0}: chose {1} of {2} heard", name, new TreeSet<>(now), known.size());
    }
  }

  /**
   * Whether a newcomer waits before choosing out of all it heard, beyond its first contact (and the
   * {@link #early} choice): it hears the others over an announcement interval, and a choice made on
   * part of them dials containers that the choice on all of them does not: a finger's place in its
   * interval is hashed over the containers in it, and the ring's successors shift, so one container
   * not heard yet moves them. Those links stay. Routing tells, once the first link's states are
   * applied, which containers there are: it waits until then (until routing reaches half of those
   * heard) and until it has heard every one routing reaches, or for {@link #HOLD_MAX_INTERVALS}
   * announcement intervals after the first choice (containers beyond discovery's reach, behind a
   * bridging container, are never heard). Guarded by this.
   */
  private boolean holding() {
    long now = scheduler.nanoTime();
    if (firstChoiceAt == 0) {
      firstChoiceAt = now;
      return false;
    }
    return holds(now - firstChoiceAt, holdMax, known.keySet(), reachable.get());
  }

  /**
   * The rule of {@link #holding}: whether to wait, {@code sinceFirst} nanoseconds after the first
   * choice and at most {@code holdMax}, having heard {@code heard} while routing reaches
   * {@code reachable}.
   */
  static boolean holds(long sinceFirst, long holdMax, Set<UUID> heard, Set<UUID> reachable) {
    if (sinceFirst >= holdMax || heard.size() <= 1) {
      return false; // waited long enough, or nothing to choose between
    }
    // Routing far behind discovery (the first link's states not applied yet; a few containers
    // heard but not reachable are normal in a growing system: they have just started), or one
    // that routing reaches not heard yet. Choosing without it would not choose what the containers
    // that answered chose for this one (they know it), and would dial others.
    return reachable.size() * 2L < heard.size() || !heard.containsAll(reachable);
  }

  /**
   * What a newcomer dials while it holds: the overlay's choice out of those that answered it (and
   * are known). Each answered because by all it knows this newcomer chooses it ({@link #answers(
   * UUID, UUID, Collection)}), so the overlay picks out of them what it would pick out of everyone,
   * as far as they answered. Those heard only from the group wait for the hold.
   */
  static Set<UUID> early(UUID self, Set<UUID> answered, Set<UUID> known, Set<UUID> linked) {
    List<UUID> members = new ArrayList<>(answered.size());
    for (UUID a : answered) {
      if (known.contains(a)) {
        members.add(a);
      }
    }
    return members.isEmpty() ? Set.of() : Set.copyOf(Overlay.chosen(self, members, linked));
  }

  private Set<UUID> linkedNow() {
    Set<UUID> result = new HashSet<>();
    for (UUID peer : known.keySet()) {
      if (linked.test(peer)) {
        result.add(peer);
      }
    }
    return result;
  }

  /** Dials {@code peer} unless linked or a dial is under way (see the class comment for when). */
  private void consider(UUID peer) {
    if (linked.test(peer)) {
      return;
    }
    long now = scheduler.nanoTime();
    Long since = dialling.get(peer);
    if (since != null && now - since < TimeUnit.MILLISECONDS.toNanos(DIAL_GRACE_MS)) {
      return; // a dial is under way
    }
    dialling.put(peer, now);
    if (dialsAtOnce(self, peer, known.keySet())) {
      dial(peer);
    } else {
      later(() -> {
        if (!linked.test(peer) && wanted.contains(peer)) {
          dial(peer);
        }
      }, SECOND_SIDE_DELAY_MS);
    }
  }

  /**
   * Whether {@code self}, knowing {@code known} (itself not among them), dials {@code peer} at once:
   * when it has the smaller id, or when by its view of the membership the peer does not choose it
   * back. The peer's choice is computed with {@code self} among the members: without it, the peer
   * never seemed to choose this container, both dialled at once, and one of the two links was then
   * closed as a duplicate, at times before the other side had the link that stays (a spurious
   * "left" and "joined").
   */
  static boolean dialsAtOnce(UUID self, UUID peer, Collection<UUID> known) {
    if (LinkReferee.compareIds(self, peer) < 0) {
      return true;
    }
    Set<UUID> members = new HashSet<>(known);
    members.add(self);
    return !Overlay.chooses(peer, self, members);
  }

  private void dial(UUID peer) {
    Heard h = known.get(peer);
    if (h == null) {
      return;
    }
    Announcement a = h.announcement();
    LOG.log(Level.DEBUG, "{0}: dialling {1} ({2}) at {3}", name, a.containerName(), peer,
        a.addresses());
    for (InetSocketAddress address : a.addresses()) {
      connector.connectOnce(address); // in parallel: the first to finish its handshake wins
    }
  }

  /**
   * Once a second: drops containers that stopped announcing, dials chosen containers whose link
   * was lost (or whose dial failed), and forgets old bookkeeping; at {@code now}, on the timer.
   */
  private void sweep(long now) {
    boolean changed = known.entrySet().removeIf(e -> now - e.getValue().atNanos() > expiry
        && !linked.test(e.getKey()));
    dialling.values().removeIf(t -> now - t > TimeUnit.MILLISECONDS.toNanos(DIAL_GRACE_MS));
    forgotten.values().removeIf(f -> now - f[1] > FORGET_NANOS);
    answered.retainAll(known.keySet());
    if (changed) {
      membershipChanged();
    } else {
      for (UUID peer : wanted) {
        consider(peer);
      }
    }
  }

  private void later(Runnable task, long delayMs) {
    try {
      scheduler.timer().schedule(task, delayMs, TimeUnit.MILLISECONDS);
    } catch (RejectedExecutionException e) {
      // The container is closing.
    }
  }

  /** Stops discovery, if it started (the container closes). */
  @Override
  public void close() {
    synchronized (switches) {
      if (discovery != null) {
        sweep.cancel(false);
        discovery.close();
      }
    }
  }
}
