package dev.trade.internal.net.mesh;

import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The service tables of other containers known here: those of containers with a route from here
 * are listed in the registry, the others wait here, the newest version of each.
 *
 * <p>A table can arrive before the link states that connect its owner: floods of tables and of
 * link states take different paths, and an edge counts only once the states of both its ends are
 * here. And while link states of a growing overlay travel, a container can look cut off for a
 * moment. Listing such a table would announce services that nobody here can call, and end in a
 * "left" for a container that is alive; dropping it would mean fetching it again. So it waits
 * until its owner is routable, and is forgotten after a grace period (the owner left).
 *
 * <p>Not thread-safe: the network's control thread owns it.
 */
final class TableKeeper {
  private static final Logger LOG = System.getLogger("dev.trade.net");

  private record Waiting(Table table, long since) {}

  private final Registry registry;
  private final Map<String, Waiting> waiting = new HashMap<>();
  private final long graceNanos;

  TableKeeper(Registry registry, long graceNanos) {
    this.registry = registry;
    this.graceNanos = graceNanos;
  }

  /** Whether a table or delta of {@code owner} at {@code version} is not newer than the one here. */
  boolean isStale(String owner, long version) {
    Waiting w = waiting.get(owner);
    return registry.isStale(owner, version) || (w != null && w.table().version() >= version);
  }

  /**
   * Takes a table newer than the one known (callers check {@link #isStale}): listed if its owner
   * has a route, else kept until it has one.
   *
   * @return whether it is new here, and to be passed on
   */
  boolean table(Table table, Topology.Route route, long nowNanos) {
    if (route != null) {
      return registry.applyTables(List.of(table), Map.of(table.containerId(), route.distance()));
    }
    Waiting was = waiting.get(table.containerId());
    waiting.put(table.containerId(), new Waiting(table, was == null ? nowNanos : was.since()));
    return true;
  }

  /** Applies a delta to the table of {@code owner}, listed or waiting; GAP when it does not follow. */
  Registry.DeltaResult delta(String owner, long version, List<ServiceDescriptor> add,
      List<Long> remove, Topology.Route route) {
    if (route != null) {
      return registry.applyDelta(owner, version, add, remove, route.distance());
    }
    Waiting w = waiting.get(owner);
    if (w == null || w.table().version() != version - 1) {
      return Registry.DeltaResult.GAP;
    }
    Map<Long, ServiceDescriptor> services = new LinkedHashMap<>();
    for (ServiceDescriptor d : w.table().services()) {
      services.put(d.serviceId(), d);
    }
    remove.forEach(services::remove);
    for (ServiceDescriptor d : add) {
      services.put(d.serviceId(), d);
    }
    waiting.put(owner, new Waiting(new Table(owner, version,
        new ArrayList<>(services.values())), w.since()));
    return Registry.DeltaResult.APPLIED;
  }

  /**
   * Names the container, as every other line does; its id, which a user rarely needs and which
   * changes at every start, only at DEBUG. A container's name travels in its services only.
   */
  private static void logLeft(String owner, Table table) {
    if (table == null || table.services().isEmpty()) {
      LOG.log(Level.INFO, "a container with no services left or is not reachable any more");
    } else {
      LOG.log(Level.INFO, "container {0} left or is not reachable any more",
          table.services().get(0).containerName());
    }
    LOG.log(Level.DEBUG, "the container that left is {0}", owner);
  }

  /** Every table of another container known here, listed or waiting (for digests and requests). */
  List<Table> known() {
    List<Table> result = registry.remoteTables();
    waiting.values().forEach(w -> result.add(w.table()));
    return result;
  }

  /**
   * Follows new routes: listed containers without a route wait from now on (their services leave
   * the registry), waiting ones with a route are listed, and the others' distances follow.
   *
   * @param moved the containers whose distance changed, with the new one
   */
  void follow(Map<String, Topology.Route> routes, Map<String, Integer> moved, long nowNanos) {
    for (String owner : registry.remoteContainers()) {
      if (!routes.containsKey(owner)) {
        Table t = registry.removeContainer(owner);
        logLeft(owner, t);
        if (t != null) {
          waiting.put(owner, new Waiting(t, nowNanos)); // listed again if reachable again soon
        }
      }
    }
    List<Table> listed = new ArrayList<>();
    Map<String, Integer> distances = new HashMap<>();
    for (Iterator<Waiting> it = waiting.values().iterator(); it.hasNext(); ) {
      Table t = it.next().table();
      Topology.Route r = routes.get(t.containerId());
      if (r != null) {
        it.remove();
        listed.add(t);
        distances.put(t.containerId(), r.distance());
      }
    }
    if (!moved.isEmpty() || !listed.isEmpty()) {
      registry.followRoutes(moved, listed, distances);
    }
  }

  /**
   * When {@link #prune} will next forget a table (nanoTime), or {@code Long.MAX_VALUE} when none
   * waits.
   */
  long forgetsAt() {
    long first = Long.MAX_VALUE;
    for (Waiting w : waiting.values()) {
      if (first == Long.MAX_VALUE || w.since() - first < 0) {
        first = w.since();
      }
    }
    return first == Long.MAX_VALUE ? first : first + graceNanos + 1;
  }

  /** Forgets tables that waited longer than the grace period. */
  void prune(long nowNanos) {
    waiting.values().removeIf(w -> nowNanos - w.since() > graceNanos);
  }
}
