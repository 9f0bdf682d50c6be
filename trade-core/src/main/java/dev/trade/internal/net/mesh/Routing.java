package dev.trade.internal.net.mesh;

import dev.trade.internal.net.link.ControlScheduler;
import dev.trade.internal.registry.Registry;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.function.BiConsumer;
import java.util.function.Consumer;

/**
 * Follows the topology: computes routes when link states change, publishes the next hop towards
 * each container, and lets the tables, pending calls and discovery follow when containers become
 * reachable or unreachable.
 *
 * <p>Routes for received link states are computed once the frames queued on the control thread
 * now have been handled, not after each, and at most once per {@link #GAP_NANOS}: at start-up
 * every container's states arrive in bursts, and each computation walks the whole graph. Changes
 * of this container's own links are followed at once: they make a new link usable (the first call
 * to a container that just started waits for it), without waiting for the peer's state.
 *
 * <p>{@link #nextHop} is safe for concurrent use; everything else runs on the control thread.
 */
final class Routing {
  /** The least time between two route computations for other containers' link states. */
  private static final long GAP_NANOS = 20_000_000L;
  private static final long PRUNE_GAP_NANOS = 1_000_000_000L;

  private final Topology topology;
  private final TableKeeper tables;
  private final Registry registry;
  private final FloodFilter filter;
  private final Consumer<UUID> unreachable;
  private final ControlScheduler scheduler;
  private final BiConsumer<UUID, String> askForTable;
  private final Consumer<String> passOnAgain;
  private final long graceNanos;
  private volatile Map<UUID, UUID> nextHops = Map.of();
  /** The routes {@link #nextHops} and the registry follow (the last computed). */
  private Map<String, Topology.Route> routed = Map.of();
  private final Map<String, UUID> ids = new HashMap<>();
  private boolean pending;
  /** When routes were last computed, unreachable states last pruned, and a hold-down ends. */
  private long computedAt;
  private long prunedAt;
  private long refreshAt;
  /** When a prune is scheduled (nanoTime), or 0. */
  private long pruneAt;

  /**
   * @param unreachable told of each container that was reachable and is not any more
   * @param askForTable asks the neighbour (first argument) for the table of a container (second)
   * @param passOnAgain floods the state of a container reachable again after it was lost (see
   *     {@link Topology#statesToShare})
   * @param graceNanos how long states and tables of unreachable containers are kept
   */
  Routing(Topology topology, TableKeeper tables, Registry registry, FloodFilter filter,
      Consumer<UUID> unreachable, ControlScheduler scheduler,
      BiConsumer<UUID, String> askForTable, Consumer<String> passOnAgain, long graceNanos) {
    this.topology = topology;
    this.tables = tables;
    this.registry = registry;
    this.filter = filter;
    this.unreachable = unreachable;
    this.scheduler = scheduler;
    this.askForTable = askForTable;
    this.passOnAgain = passOnAgain;
    this.graceNanos = graceNanos;
  }

  /** The neighbour on the shortest path to {@code container}, or null. Any thread. */
  UUID nextHop(UUID container) {
    return nextHops.get(container);
  }

  /** The other containers there are routes to now: an immutable snapshot. Any thread. */
  Set<UUID> reachable() {
    return nextHops.keySet();
  }

  /** The route to {@code container} as computed last, or null. */
  Topology.Route route(String container) {
    return routed.get(container);
  }

  /** A received link state changed the topology. */
  void changedSoon() {
    if (pending) {
      return; // a computation is queued
    }
    pending = true;
    long wait = Math.max(0, computedAt + GAP_NANOS - topology.nanoTime());
    scheduler.schedule(() -> {
      if (pending) {
        follow();
      }
    }, wait);
  }

  /** Computes routes now, and lets everything follow them. */
  void follow() {
    pending = false;
    long now = topology.nanoTime();
    computedAt = now;
    Map<String, Topology.Route> routes = topology.routes();
    if (now - prunedAt >= PRUNE_GAP_NANOS) {
      prunedAt = now;
      topology.pruneUnreachable(now, graceNanos);
      tables.prune(now);
      filter.pruned();
      ids.keySet().retainAll(routes.keySet());
      pruneWhenDue(now, Math.min(topology.forgetsAt(graceNanos), tables.forgetsAt()));
    } else {
      pruneWhenDue(now, prunedAt + PRUNE_GAP_NANOS); // what became unreachable now is noted then
    }
    refreshAtNextHoldDownEnd();
    if (routes == routed) {
      return; // the same routes as computed last time: nothing follows
    }
    Map<String, Topology.Route> was = routed;
    routed = routes;
    Map<UUID, UUID> hops = new HashMap<>();
    Map<String, Integer> moved = new HashMap<>();
    for (Map.Entry<String, Topology.Route> r : routes.entrySet()) {
      hops.put(id(r.getKey()), id(r.getValue().nextHop()));
      Topology.Route before = was.get(r.getKey());
      if (before != null && before.distance() != r.getValue().distance()) {
        moved.put(r.getKey(), r.getValue().distance());
      }
    }
    Map<UUID, UUID> before = nextHops;
    nextHops = Map.copyOf(hops);
    tables.follow(routes, moved, now);
    topology.takeRegained().forEach(passOnAgain);
    List<String> known = registry.remoteContainers();
    for (UUID gone : before.keySet()) {
      if (!hops.containsKey(gone)) {
        unreachable.accept(gone);
      }
    }
    // A container that became reachable but whose table we lack (it travelled another way, or was
    // pruned while the path was down): ask the next hop for it. Not a new neighbour, reachable from
    // its link's first moment on: its table comes in the link-up exchange.
    for (Map.Entry<UUID, UUID> h : hops.entrySet()) {
      if (!before.containsKey(h.getKey()) && !known.contains(h.getKey().toString())
          && !h.getValue().equals(h.getKey())) {
        askForTable.accept(h.getValue(), h.getKey().toString());
      }
    }
  }

  /**
   * Computes routes again when the next hold-down ends: it may make a container reachable that no
   * new state will (its own did not change). Asked at every computation, also when the routes did
   * not change: of two hold-downs, the end of the first may change nothing, and the second would
   * then keep its container unreachable until some state changed, in a quiet system for good.
   */
  private void refreshAtNextHoldDownEnd() {
    long end = topology.nextHoldDownEnd();
    if (end != 0 && (refreshAt == 0 || end - refreshAt < 0)) {
      refreshAt = end;
      scheduler.schedule(() -> {
        refreshAt = 0;
        topology.refresh();
        follow();
      }, Math.max(0, end - topology.nanoTime()));
    }
  }

  /**
   * Prunes at {@code due} (nanoTime; {@code Long.MAX_VALUE}: nothing waits to be forgotten) unless
   * a prune is scheduled by then. Pruning comes with route computations, and after containers
   * left nothing may compute routes again: the states, tables and ids of the last ones to leave
   * stayed for good (a 1,000,000-input link fuzzing, whose peers came and went, ended some MB above
   * where it began and never came back).
   */
  private void pruneWhenDue(long now, long due) {
    if (due == Long.MAX_VALUE || (pruneAt != 0 && pruneAt - due <= 0)) {
      return;
    }
    pruneAt = due;
    scheduler.schedule(() -> {
      if (pruneAt == due) {
        pruneAt = 0;
        follow();
      }
    }, Math.max(0, due - now));
  }

  /** Whether the UUID of {@code container} is kept (for tests: only routed containers' are). */
  boolean knowsId(String container) {
    return ids.containsKey(container);
  }

  /** The id as a UUID, parsed once per container. */
  private UUID id(String container) {
    return ids.computeIfAbsent(container, UUID::fromString);
  }
}
