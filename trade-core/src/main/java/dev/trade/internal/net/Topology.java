package dev.trade.internal.net;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Link-state routing: every container floods the list of containers it has a direct link to
 * (versioned by its owner); from all lists, each container computes shortest paths (breadth-first:
 * graphs here are small) and keeps a next hop and a distance per reachable container.
 *
 * <p>An edge counts only when both ends list each other, so a dead container's stale list cannot
 * keep it reachable once its neighbours have dropped it. Routes are loop-free because each container
 * forwards along a shortest path of the same graph, and a hop limit on every forwarded frame bounds
 * the damage while views disagree.
 *
 * <p>Not thread-safe: the network's control thread owns it, but {@link #isStale} may be called from
 * any thread.
 */
final class Topology {
  /** A container's reported neighbours. */
  record LinkState(String owner, long version, Set<String> neighbours) {
    LinkState {
      neighbours = Set.copyOf(neighbours);
    }
  }

  /** Next hop and distance to a destination. */
  record Route(String nextHop, int distance) {}

  private final String self;
  private final Map<String, LinkState> states = new HashMap<>();
  /** Each state's neighbours, sorted once when it arrives: routes walk them in this order. */
  private final Map<String, String[]> sorted = new HashMap<>();
  /** The version of each state in {@link #states}, for {@link #isStale} on other threads. */
  private final Map<String, Long> versions = new ConcurrentHashMap<>();
  private final Map<String, Long> unreachableSince = new HashMap<>();
  /** Containers that just became unreachable: their state version then, and until when it holds. */
  private final Map<String, long[]> holdDown = new HashMap<>();
  private final long holdDownNanos;
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
    this.self = self;
    this.holdDownNanos = holdDownNanos;
    put(new LinkState(self, 0, Set.of()));
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
    put(s);
    stale = true;
    return true;
  }

  private void put(LinkState s) {
    states.put(s.owner(), s);
    versions.put(s.owner(), s.version());
    String[] n = s.neighbours().toArray(new String[0]);
    Arrays.sort(n);
    sorted.put(s.owner(), n);
  }

  /** Every known state (to send to a new neighbour). */
  List<LinkState> states() {
    return List.copyOf(states.values());
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
   * Forgets the states of containers that have been unreachable for longer than {@code graceNanos}
   * (they left or died; a restarted container has a new id). States of unreachable containers are
   * kept for a while because a state may arrive before the states that connect its owner to us.
   */
  void pruneUnreachable(long nowNanos, long graceNanos) {
    fresh();
    for (String owner : states.keySet()) {
      if (owner.equals(self) || routes.containsKey(owner)) {
        unreachableSince.remove(owner);
      } else {
        unreachableSince.putIfAbsent(owner, nowNanos);
      }
    }
    unreachableSince.entrySet().removeIf(e -> {
      if (nowNanos - e.getValue() > graceNanos) {
        states.remove(e.getKey());
        versions.remove(e.getKey());
        sorted.remove(e.getKey());
        return true;
      }
      return !states.containsKey(e.getKey());
    });
  }

  /** Whether {@code container} is held unreachable now (see the constructor). */
  boolean isHeldDown(String container) {
    fresh();
    long[] h = holdDown.get(container);
    if (h == null) {
      return false;
    }
    LinkState s = states.get(container);
    return System.nanoTime() - h[1] < 0 && (s == null || s.version() <= h[0]);
  }

  /** Recomputes routes now (a hold-down may have ended). */
  void refresh() {
    recompute();
  }

  private void recompute() {
    stale = false;
    long now = System.nanoTime();
    holdDown.values().removeIf(h -> now - h[1] >= 0);
    Map<String, Route> before = routes;
    Map<String, Route> result = new HashMap<>();
    Queue<String> queue = new ArrayDeque<>();
    for (String n : neighboursOf(self)) {
      result.put(n, new Route(n, 1));
      queue.add(n);
    }
    while (!queue.isEmpty()) {
      String at = queue.poll();
      Route via = result.get(at);
      for (String n : neighboursOf(at)) {
        if (!n.equals(self) && !result.containsKey(n) && !isHeldDown(n)) {
          result.put(n, new Route(via.nextHop(), via.distance() + 1));
          queue.add(n);
        }
      }
    }
    if (!result.equals(before)) {
      routes = Collections.unmodifiableMap(result); // unchanged routes keep their instance
    }
    holdDown.keySet().removeAll(result.keySet()); // a direct link proves it alive
    for (String gone : before.keySet()) {
      if (!result.containsKey(gone)) {
        LinkState s = states.get(gone);
        holdDown.put(gone, new long[] {s == null ? Long.MAX_VALUE : s.version(), now + holdDownNanos});
      }
    }
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

  /** Neighbours of {@code node} that list {@code node} back, sorted for determinism. */
  private List<String> neighboursOf(String node) {
    String[] listed = sorted.get(node);
    if (listed == null) {
      return List.of();
    }
    List<String> result = new ArrayList<>(listed.length);
    for (String n : listed) {
      LinkState back = states.get(n);
      if (back != null && back.neighbours().contains(node)) {
        result.add(n);
      }
    }
    return result;
  }
}
