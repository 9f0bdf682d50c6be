package dev.trade.internal.net.mesh;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.LongSupplier;

/**
 * Link-state routing: every container floods the list of containers it has a direct link to
 * (versioned by its owner); from all lists, each container computes shortest paths (breadth-first:
 * graphs here are small) and keeps a next hop and a distance per reachable container.
 *
 * <p>An edge counts only when both ends list each other, so a dead container's stale list cannot
 * keep it reachable once its neighbours have dropped it; this container's own links count as soon
 * as it lists them (it knows they are alive), so that a new link carries calls before the peer's
 * state arrives. Routes are loop-free because each container
 * forwards along a shortest path of the same graph, and a hop limit on every forwarded frame bounds
 * the damage while views disagree.
 *
 * <p>Not thread-safe: the network's control thread owns it, but {@link #isStale} may be called from
 * any thread.
 */
public final class Topology {
  /** A container's reported neighbours. */
  public record LinkState(String owner, long version, Set<String> neighbours) {
    public LinkState {
      neighbours = Set.copyOf(neighbours);
    }
  }

  /** Next hop and distance to a destination. */
  record Route(String nextHop, int distance) {}

  private final String self;
  private final Map<String, LinkState> states = new HashMap<>();
  /** The states as numbered nodes, for route computations. */
  private final Graph graph = new Graph();
  // The last computation, by node number, to tell quickly whether routes changed.
  private int[] distance = new int[0];
  private int[] firstHop = new int[0];
  private int[] lastDistance = new int[0];
  private int[] lastFirstHop = new int[0];
  private int lastGeneration;
  /** The version of each state in {@link #states}, for {@link #isStale} on other threads. */
  private final Map<String, Long> versions = new ConcurrentHashMap<>();
  private final Map<String, Long> unreachableSince = new HashMap<>();
  /** Containers that were reachable and are not now: what is known of them may be stale. */
  private final Set<String> lost = new HashSet<>();
  /** Lost containers reachable again since {@link #takeRegained} was last called. */
  private final List<String> regained = new ArrayList<>();
  /** Containers that just became unreachable: their state version then, and until when it holds. */
  private final Map<String, long[]> holdDown = new HashMap<>();
  private final long holdDownNanos;
  /** nanoTime, for hold-downs here and for {@link Routing}'s decisions. */
  private final LongSupplier clock;
  private long ownVersion;
  private Map<String, Route> routes = Map.of();
  /** States changed since routes were computed: they are computed again when next read. */
  private boolean stale;

  /**
   * @param holdDownNanos how long a container that became unreachable stays so unless it shows it
   *     is alive (a newer link state of its own): neighbours notice a death at different moments,
   *     and a late neighbour's stale state must not bring a dead container back
   */
  Topology(String self, long holdDownNanos) {
    this(self, holdDownNanos, System::nanoTime);
  }

  /** @param clock nanoTime: the JVM's, or a test's */
  Topology(String self, long holdDownNanos, LongSupplier clock) {
    this.self = self;
    this.holdDownNanos = holdDownNanos;
    this.clock = clock;
    put(new LinkState(self, 0, Set.of()));
  }

  long nanoTime() {
    return clock.getAsLong();
  }

  /** Sets this container's own neighbours; returns the new own state to flood. */
  LinkState setOwnNeighbours(Set<String> neighbours) {
    LinkState s = new LinkState(self, ++ownVersion, neighbours);
    put(s);
    recompute();
    return s;
  }

  LinkState own() {
    return states.get(self);
  }

  /** Whether a state of {@code owner} at {@code version} would change nothing (see apply). Any thread. */
  boolean isStale(String owner, long version) {
    Long known = versions.get(owner);
    return owner.equals(self) || (known != null && known >= version);
  }

  /**
   * Applies another container's state; true when it was newer than what was known. Routes are
   * computed again when next read, not here: a burst of n states then costs one computation.
   */
  boolean apply(LinkState s) {
    if (s.owner().equals(self)) {
      return false;
    }
    LinkState known = states.get(s.owner());
    if (known != null && known.version() >= s.version()) {
      return false;
    }
    put(shared(s));
    stale = true;
    return true;
  }

  /**
   * The state with the graph's one instance of each id. The ids of a received state are new
   * strings read from its frame and live until its next version: with 100 containers, sharing them
   * took a 25-container JVM from about 90,000 live strings to 41,000, and its young-collection
   * pauses in the first 25 s from about 4.6 s to 1.8–3.0 s.
   */
  private LinkState shared(LinkState s) {
    String[] neighbours = new String[s.neighbours().size()];
    int i = 0;
    for (String n : s.neighbours()) {
      neighbours[i++] = graph.name(graph.node(n));
    }
    // Distinct ids of a set: Set.of takes them, and the state keeps that set without a copy.
    return new LinkState(graph.name(graph.node(s.owner())), s.version(), Set.of(neighbours));
  }

  private void put(LinkState s) {
    states.put(s.owner(), s);
    versions.put(s.owner(), s.version());
    graph.put(s.owner(), s.neighbours());
  }

  /** Every known state (for this container's own digest). */
  List<LinkState> states() {
    return List.copyOf(states.values());
  }

  /**
   * The states to give a new neighbour: all but those of containers this one lost (was routing
   * to, and is not now). Those may be stale: when a container dies and splits the system in two,
   * each side keeps its last state of the other side, which still lists the dead one, and a
   * successor linking both sides would route to the dead container through them. Whoever reaches
   * a lost container gives its state instead, and this container passes it on again once it
   * reaches it again ({@link #takeRegained}).
   */
  List<LinkState> statesToShare() {
    fresh();
    List<LinkState> result = new ArrayList<>(states.size());
    for (LinkState s : states.values()) {
      if (!lost.contains(s.owner())) {
        result.add(s);
      }
    }
    return result;
  }

  /** Whether this container lost {@code container}: had a route to it, and has none now. */
  boolean isLost(String container) {
    fresh();
    return lost.contains(container);
  }

  /** The containers lost and reachable again since the last call, whose states to pass on again. */
  List<String> takeRegained() {
    fresh();
    if (regained.isEmpty()) {
      return List.of();
    }
    List<String> result = List.copyOf(regained);
    regained.clear();
    return result;
  }

  /** The state of {@code owner}, or null. */
  LinkState state(String owner) {
    return states.get(owner);
  }

  /** The route to {@code container}, or null when it is not reachable. */
  Route route(String container) {
    fresh();
    return routes.get(container);
  }

  /**
   * Reachable containers other than this one, with their routes: the same instance as last time
   * when they did not change.
   */
  Map<String, Route> routes() {
    fresh();
    return routes;
  }

  private void fresh() {
    if (stale) {
      recompute();
    }
  }

  /**
   * Forgets the states of containers that have been unreachable for longer than {@code graceNanos},
   * and that they were lost (they left or died; a restarted container has a new id). States of
   * unreachable containers are kept for a while because a state may arrive before the states that
   * connect its owner to us.
   */
  void pruneUnreachable(long nowNanos, long graceNanos) {
    fresh();
    for (String owner : states.keySet()) {
      noteReachability(owner, nowNanos);
    }
    // A neighbour that left before its own state came is lost without a state: this is all that
    // is kept of it, and it was kept for good (a set of every such id ever seen).
    for (String owner : lost) {
      noteReachability(owner, nowNanos);
    }
    unreachableSince.entrySet().removeIf(e -> {
      if (nowNanos - e.getValue() > graceNanos) {
        lost.remove(e.getKey());
        states.remove(e.getKey());
        versions.remove(e.getKey());
        graph.remove(e.getKey());
        return true;
      }
      return !states.containsKey(e.getKey()) && !lost.contains(e.getKey());
    });
  }

  private void noteReachability(String owner, long nowNanos) {
    if (owner.equals(self) || routes.containsKey(owner)) {
      unreachableSince.remove(owner);
    } else {
      unreachableSince.putIfAbsent(owner, nowNanos);
    }
  }

  /**
   * When {@link #pruneUnreachable} with {@code graceNanos} will next forget a state (nanoTime), or
   * {@code Long.MAX_VALUE} when no state waits for it.
   */
  long forgetsAt(long graceNanos) {
    long first = Long.MAX_VALUE;
    for (long since : unreachableSince.values()) {
      if (first == Long.MAX_VALUE || since - first < 0) {
        first = since;
      }
    }
    return first == Long.MAX_VALUE ? first : first + graceNanos + 1;
  }

  /** Whether {@code container} is held unreachable now (see the constructor). */
  boolean isHeldDown(String container) {
    fresh();
    return heldDown(container, nanoTime());
  }

  /** Recomputes routes now (a hold-down may have ended). */
  void refresh() {
    recompute();
  }

  private void recompute() {
    stale = false;
    long now = nanoTime();
    holdDown.values().removeIf(h -> now - h[1] >= 0);
    int n = graph.size();
    if (distance.length < n || (distance.length > 64 && distance.length > 4 * n)) {
      distance = new int[2 * n]; // also smaller again once the graph was renumbered smaller
      firstHop = new int[2 * n];
    }
    int from = graph.node(self);
    graph.shortestPaths(from, distance, firstHop,
        holdDown.isEmpty() ? node -> false : node -> heldDown(graph.name(node), now));
    distance[from] = -1; // not a route
    for (int i = 0; i < n; i++) {
      if (distance[i] < 0) {
        firstHop[i] = -1;
      }
    }
    if (n == lastDistance.length && graph.generation() == lastGeneration
        && Arrays.equals(distance, 0, n, lastDistance, 0, n)
        && Arrays.equals(firstHop, 0, n, lastFirstHop, 0, n)) {
      return; // unchanged routes keep their instance
    }
    lastGeneration = graph.generation();
    lastDistance = Arrays.copyOf(distance, n);
    lastFirstHop = Arrays.copyOf(firstHop, n);
    Map<String, Route> before = routes;
    Map<String, Route> result = new HashMap<>();
    for (int i = 0; i < n; i++) {
      if (distance[i] > 0) {
        result.put(graph.name(i), new Route(graph.name(firstHop[i]), distance[i]));
      }
    }
    if (result.equals(before)) {
      return; // the same routes, numbered differently
    }
    routes = Collections.unmodifiableMap(result);
    holdDown.keySet().removeAll(result.keySet()); // a direct link proves it alive
    for (String reached : result.keySet()) {
      if (lost.remove(reached)) {
        regained.add(reached);
      }
    }
    for (String gone : before.keySet()) {
      if (!result.containsKey(gone)) {
        lost.add(gone);
        LinkState s = states.get(gone);
        holdDown.put(gone, new long[] {s == null ? Long.MAX_VALUE : s.version(), now + holdDownNanos});
      }
    }
  }

  private boolean heldDown(String container, long now) {
    long[] h = holdDown.get(container);
    if (h == null) {
      return false;
    }
    LinkState s = states.get(container);
    return now - h[1] < 0 && (s == null || s.version() <= h[0]);
  }

  /** When the earliest hold-down ends (nanoTime), or 0 when none is in force. */
  long nextHoldDownEnd() {
    fresh();
    long next = 0;
    for (long[] h : holdDown.values()) {
      if (next == 0 || h[1] - next < 0) {
        next = h[1];
      }
    }
    return next;
  }
}
