package dev.trade.internal.net.mesh;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.net.link.ControlScheduler;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.Executor;
import java.util.function.Consumer;

/**
 * Keeps every container's view of the system in step: link states (for routing) and service
 * tables, each versioned by its owner and flooded over all links. A frame that changes nothing here
 * (a version already known) is not passed on, so floods end. A new neighbour gets what it lacks
 * ({@link Digest}), or everything if it does not exchange digests. TableKeeper of containers without a
 * route from here wait until they have one ({@link TableKeeper}).
 *
 * <p>Everything but {@link #nextHop} and {@link #localChanged} runs on the network's control thread.
 */
public final class Replication {
  /** How long the link state of an unreachable container is kept (it may be reachable soon). */
  private static final long STATE_GRACE_NANOS = 60_000_000_000L;
  /** The least time between two floods of this container's own link state, but see linkDown. */
  static final long OWN_FLOOD_GAP_NANOS = 50_000_000L;

  private final String selfId;
  private final Registry registry;
  private final Codec tableCodec;
  private final Map<UUID, Link> links;
  private final Topology topology;

  private final ControlScheduler scheduler;
  /** When this container's own link state last went out (nanoTime), and which version. */
  private long ownFloodAt;
  private long ownFlooded;
  private boolean ownFloodPending;
  private Set<String> ownFloodedNeighbours = Set.of();
  /**
   * New links whose peer's DIGEST has not been answered yet. They get no floods until then: the
   * answer carries everything current, and a table flooded before it would arrive ahead of the
   * link states that route to its owner.
   */
  private final Set<Link> unanswered = new HashSet<>();
  private final FloodFilter filter;
  /** Links with frames queued by {@link #send} and not written yet. */
  private final Set<Link> queued = new LinkedHashSet<>();
  private final TableKeeper tables;
  private final Routing routing;

  /**
   * @param holdDownNanos how long a container that became unreachable stays so unless it proves
   *     alive (see {@link Topology})
   * @param unreachable told, on the control thread, of each container that was reachable and is not
   *     any more
   */
  public Replication(UUID self, Registry registry, Codec tableCodec, Map<UUID, Link> links,
      long holdDownNanos, ControlScheduler scheduler, Consumer<UUID> unreachable) {
    this.scheduler = scheduler;
    this.selfId = self.toString();
    this.registry = registry;
    this.tableCodec = tableCodec;
    this.links = links;
    this.topology = new Topology(selfId, holdDownNanos);
    this.tables = new TableKeeper(registry, STATE_GRACE_NANOS);
    this.filter = new FloodFilter(topology, registry, tables);
    this.routing = new Routing(topology, tables, registry, filter, unreachable, scheduler,
        (hop, owner) -> {
          Link via = links.get(hop);
          if (via != null) {
            send(via, StateFrames.tableRequest(owner));
          }
        }, owner -> {
          Topology.LinkState s = topology.state(owner);
          if (s != null) { // neighbours linked while it was lost were not given it
            passOn(s, StateFrames.links(s), null);
          }
        }, STATE_GRACE_NANOS);
  }

  /** See {@link FloodFilter#isStale}. Any thread. */
  public boolean isStale(Link from, int type, byte[] buf, int off, int len) {
    return filter.isStale(from, type, buf, off, len);
  }

  /** The other containers there are routes to now: an immutable snapshot. Any thread. */
  public Set<UUID> reachable() {
    return routing.reachable();
  }

  /** The neighbour on the shortest path to {@code container}, or null. Any thread. */
  public UUID nextHop(UUID container) {
    return routing.nextHop(container);
  }

  public void linkUp(Link link) {
    ownNeighboursChanged();
    floodOwnSoon(link);
    if (link.digests) {
      // What the peer lacks follows its own DIGEST (received below).
      unanswered.add(link);
      send(link, Digest.frame(topology.states(), registry.localTable(), tables.known()));
      return;
    }
    for (Topology.LinkState s : topology.statesToShare()) {
      send(link, StateFrames.links(s));
    }
    send(link, StateFrames.table(tableCodec, registry.localTable()));
    for (Table t : tablesToShare()) {
      send(link, StateFrames.table(tableCodec, t));
    }
  }

  /**
   * The tables to give a new neighbour: as with link states, none of containers this one lost.
   * Those left or died, and a table kept for one (it may come back) must not be given on: a
   * newcomer would keep it, without a route, and give it to the next newcomer after this container
   * had forgotten it, which would then take it for new. With containers coming and going, the
   * tables of containers long gone went round so for good, in every container's memory and in
   * every newcomer's link-up. Whoever reaches a lost container gives its table, or answers the
   * TABLE_REQUEST of a container that comes to reach it.
   */
  private List<Table> tablesToShare() {
    List<Table> known = tables.known();
    known.removeIf(t -> topology.isLost(t.containerId()));
    return known;
  }

  /** Any link that closed, the neighbour's or a duplicate retired: nothing here may keep it. */
  public void linkClosed(Link link) {
    filter.forget(link);
  }

  public void linkDown(Link link) {
    unanswered.remove(link);
    // At once, whatever was sent last: this is how every container learns quickly that a dead
    // neighbour's link is gone (an edge counts only while both ends list it).
    floodOwn(ownNeighboursChanged(), null);
  }

  /**
   * Floods this container's own link state at once after a quiet period, else once when
   * {@link #OWN_FLOOD_GAP_NANOS} has passed since the last flood, with whatever is current then:
   * a container that gains d links at start-up floods a few versions, not d, and every version
   * reaches every container over every link.
   *
   * @param except a new link that gets the current state in the link-up exchange, or null
   */
  private void floodOwnSoon(Link except) {
    long since = System.nanoTime() - ownFloodAt;
    if (ownFloodPending) {
      return;
    }
    if (ownFlooded == 0 || since >= OWN_FLOOD_GAP_NANOS) {
      floodOwn(topology.own(), except);
      return;
    }
    ownFloodPending = true;
    scheduler.schedule(() -> {
      ownFloodPending = false;
      if (topology.own().version() > ownFlooded) {
        floodOwn(topology.own(), null);
      }
    }, OWN_FLOOD_GAP_NANOS - since);
  }

  /**
   * Floods this container's own state now if the last one flooded does not list {@code from} yet:
   * a table passed on from a new neighbour must not overtake the state that routes to its owner,
   * or receivers would list services that they cannot call yet.
   */
  private void ownStateBefore(Link from) {
    if (ownFloodPending && !ownFloodedNeighbours.contains(from.peerKey)
        && topology.own().version() > ownFlooded) {
      floodOwn(topology.own(), null);
    }
  }

  private void floodOwn(Topology.LinkState own, Link except) {
    ownFloodAt = System.nanoTime();
    ownFlooded = own.version();
    ownFloodedNeighbours = own.neighbours();
    flood(StateFrames.links(own), except);
  }

  private Topology.LinkState ownNeighboursChanged() {
    Set<String> ids = new HashSet<>();
    links.keySet().forEach(id -> ids.add(id.toString()));
    Topology.LinkState own = topology.setOwnNeighbours(ids);
    routing.follow();
    return own;
  }

  /** Called by the registry, under its lock, for every change: ships this container's own. */
  public void localChanged(List<Entry> added, List<Entry> removed, Executor control) {
    List<ServiceDescriptor> add = new ArrayList<>();
    for (Entry e : added) {
      if (e.local() != null) {
        add.add(e.descriptor());
      }
    }
    List<Long> remove = new ArrayList<>();
    for (Entry e : removed) {
      if (e.local() != null) {
        remove.add(e.descriptor().serviceId());
      }
    }
    if (add.isEmpty() && remove.isEmpty()) {
      return;
    }
    long version = registry.localVersion();
    control.execute(() -> flood(StateFrames.delta(tableCodec, selfId, version, add, remove), null));
  }

  public void received(Link from, int type, byte[] payload) {
    ByteSource in = ByteSource.of(payload);
    try {
      switch (type) {
        case Wire.LINKS: {
          String owner = StateFrames.containerId(in);
          long version = in.readLong();
          if (topology.isStale(owner, version) || filter.superseded(type, owner, version)) {
            break; // a copy that came another way first (most frames of a flood), or outdated
          }
          int n = in.readVarUInt();
          if (n > 65_536) {
            throw new IOException("link state with " + n + " neighbours");
          }
          Set<String> neighbours = new HashSet<>();
          for (int i = 0; i < n; i++) {
            neighbours.add(StateFrames.containerId(in));
          }
          Topology.LinkState state = new Topology.LinkState(owner, version, neighbours);
          if (topology.apply(state)) {
            passOn(state, StateFrames.wrap(Wire.LINKS, payload), from);
            routing.changedSoon();
          }
          break;
        }
        case Wire.TABLE: {
          String owner = StateFrames.containerId(in);
          long version = in.readLong();
          if (tables.isStale(owner, version) || filter.superseded(type, owner, version)) {
            break; // not decoded
          }
          List<ServiceDescriptor> services =
              StateFrames.descriptors(tableCodec.read(in, loader()), owner);
          // Routes as computed last: a table whose owner is not routable yet is listed once it is.
          if (!tables.table(new Table(owner, version, services), routing.route(owner),
              System.nanoTime())) {
            break;
          }
          ownStateBefore(from);
          flood(StateFrames.wrap(Wire.TABLE, payload), from);
          break;
        }
        case Wire.DELTA: {
          String owner = StateFrames.containerId(in);
          long version = in.readLong();
          if (tables.isStale(owner, version)) {
            break;
          }
          List<ServiceDescriptor> add =
              StateFrames.descriptors(tableCodec.read(in, loader()), owner);
          List<Long> remove = StateFrames.ids(tableCodec.read(in, loader()));
          Registry.DeltaResult r = tables.delta(owner, version, add, remove, routing.route(owner));
          if (r == Registry.DeltaResult.APPLIED) {
            ownStateBefore(from);
            flood(StateFrames.wrap(Wire.DELTA, payload), from);
          } else if (r == Registry.DeltaResult.GAP) {
            send(from, StateFrames.tableRequest(owner));
          }
          break;
        }
        case Wire.TABLE_REQUEST: {
          String owner = StateFrames.containerId(in);
          if (owner.equals(selfId)) {
            send(from, StateFrames.table(tableCodec, registry.localTable()));
          } else {
            for (Table t : tables.known()) {
              if (t.containerId().equals(owner)) {
                send(from, StateFrames.table(tableCodec, t));
              }
            }
          }
          break;
        }
        case Wire.DIGEST: {
          if (!unanswered.remove(from)) {
            throw new IOException("a second DIGEST, or one on a link without digests");
          }
          List<Topology.LinkState> states = topology.statesToShare();
          for (byte[] frame : Digest.answer(payload, states, registry.localTable(), tablesToShare(),
              tableCodec)) {
            send(from, frame);
          }
          break;
        }
        default:
          break;
      }
    } catch (IOException | TRADESerializationException | RuntimeException e) {
      from.close("malformed replication frame: " + e.getMessage());
    }
  }

  private static ClassLoader loader() {
    return Replication.class.getClassLoader();
  }

  /**
   * Passes another container's link state on, as {@code frame}, to the links that may lack it:
   * not {@code from}, not the owner, not the neighbours it lists (the owner sent it to them itself:
   * it floods each new version over exactly those links, and gives all states to a link that comes
   * up later; in a full mesh passing it to them again was n - 2 copies per receiver, n^2 frames per
   * link change), nor to those that sent this version here too, or when a newer one waits
   * ({@link FloodFilter#hasCopy}).
   */
  private void passOn(Topology.LinkState state, byte[] frame, Link from) {
    for (Link l : links.values()) {
      String peer = l.peerKey;
      if (l != from && !peer.equals(state.owner()) && !state.neighbours().contains(peer)
          && !unanswered.contains(l) && !filter.hasCopy(l, state.owner(), state.version())) {
        send(l, frame);
      }
    }
  }

  private void flood(byte[] frame, Link except) {
    for (Link l : links.values()) {
      if (l != except && !unanswered.contains(l)) {
        send(l, frame);
      }
    }
  }

  /**
   * Queues a frame; {@link #flushQueued()} writes it. Floods reach every link, and a burst of
   * frames handled on the control thread then leaves with one system call per link, not one per
   * frame, and wakes each neighbour's reader once.
   */
  private void send(Link link, byte[] frame) {
    try {
      link.queue(frame);
      queued.add(link);
    } catch (IOException e) {
      // The link closed itself; its reader reports the loss.
    }
  }

  /** Writes the frames queued by the tasks handled so far. Control thread. */
  public void flushQueued() {
    for (Link l : queued) {
      try {
        l.flushQueued();
      } catch (IOException e) {
        // The link closed itself; its reader reports the loss.
      }
    }
    queued.clear();
  }
}
