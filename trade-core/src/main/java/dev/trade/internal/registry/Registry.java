package dev.trade.internal.registry;

import dev.trade.TRADERegistrationException;
import dev.trade.TRADEServiceNotFoundException;
import java.lang.annotation.Annotation;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.LinkedHashSet;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The table of every service this container knows: its own and, replicated, those of every other
 * container of the system.
 *
 * <p>Lookups read an immutable snapshot without locking; changes (rare) take the registry's lock,
 * build a new snapshot and publish it, then tell the listeners while still holding the lock, so
 * that listeners see changes exactly once and in order. Listeners must therefore only record or
 * enqueue, never block or call back into the registry's write methods.
 *
 * <p>Order: lookups return services of this container first (in registration order), then those of
 * other containers by distance, then by container id and service id: deterministic, never random.
 *
 * <p>This class is safe for concurrent use.
 */
public final class Registry {
  /** Told of every change, under the registry's lock. */
  public interface Listener {
    void changed(List<Entry> added, List<Entry> removed);

    /**
     * Container {@code containerId} left or became unreachable (after its services' removal was
     * told to {@link #changed}, and also when it had none): those who keep state for it act now
     * rather than wait for it to time out.
     */
    default void containerLeft(String containerId) {}
  }

  private final String containerId;
  private final String containerName;
  private final String host;
  private final AtomicLong nextServiceId = new AtomicLong(1);
  // Written under this' lock, read lock-free.
  private volatile LocalIndex localById = LocalIndex.EMPTY;
  private final List<Listener> listeners = new CopyOnWriteArrayList<>();
  // Guarded by this.
  private final Map<Object, List<LocalService>> byProvider = new IdentityHashMap<>();
  // Guarded by this: every known entry by container id, then service id.
  private final Map<String, Map<Long, Entry>> tables = new HashMap<>();
  // Guarded by this: the newest version applied per container (this one's own included).
  private final Map<String, Long> versions = new HashMap<>();
  private long localVersion;
  private volatile Snapshot snapshot = Snapshot.EMPTY;

  public Registry(String containerId, String containerName, String host) {
    this.containerId = containerId;
    this.containerName = containerName;
    this.host = host;
    tables.put(containerId, new LinkedHashMap<>());
  }

  public String containerId() {
    return containerId;
  }

  /** The host name this container announces, as services' hosts are compared against it. */
  public String host() {
    return host;
  }

  public void addListener(Listener l) {
    listeners.add(l);
  }

  public void removeListener(Listener l) {
    listeners.remove(l);
  }

  /**
   * Registers every service of {@code provider} in {@code groups}: all or nothing.
   *
   * @throws TRADERegistrationException if the provider is already registered, or one of its
   *     annotated methods is not a valid service (the message names it)
   */
  public List<LocalService> register(Object provider, Collection<String> groups)
      throws TRADERegistrationException {
    List<Method> methods = ServiceScanner.serviceMethods(provider.getClass());
    List<LocalService> prepared = new ArrayList<>(methods.size());
    for (Method m : methods) {
      prepared.add(ServiceScanner.prepare(provider, m, (name, names, types, ret, annotations,
          genericRet, exceptions, parameterAnnotations) -> descriptor(name, names, types, ret, groups,
          annotations, genericRet, exceptions, parameterAnnotations)));
    }
    synchronized (this) {
      if (byProvider.containsKey(provider)) {
        throw new TRADERegistrationException("Object " + describe(provider)
            + " is already registered; deregister it first to register it again");
      }
      byProvider.put(provider, prepared);
      List<Entry> added = new ArrayList<>(prepared.size());
      Map<Long, Entry> own = tables.get(containerId);
      for (LocalService s : prepared) {
        localById = localById.with(s);
        Entry e = new Entry(s.descriptor(), 0, s);
        own.put(s.descriptor().serviceId(), e);
        added.add(e);
      }
      localVersion++;
      publish(added, List.of());
    }
    return prepared;
  }

  /**
   * Removes every service of {@code provider}; calls in progress finish, later calls fail.
   *
   * @throws TRADEServiceNotFoundException if the provider is not registered here
   */
  public synchronized List<LocalService> deregister(Object provider) throws TRADEServiceNotFoundException {
    List<LocalService> services = byProvider.remove(provider);
    if (services == null) {
      throw new TRADEServiceNotFoundException("Object " + describe(provider) + " is not registered");
    }
    removeLocal(services);
    return services;
  }

  /**
   * Gives the local service {@code serviceId} the groups {@code groups}, in their order: its id
   * stays, so that handles to it keep working; lookups everywhere see the change (replicated as a
   * delta that removes the old description and adds the new one; listeners see it left and joined).
   *
   * @return the new descriptor
   * @throws TRADEServiceNotFoundException if no such service is registered here
   */
  public synchronized ServiceDescriptor setGroups(long serviceId, Collection<String> groups)
      throws TRADEServiceNotFoundException {
    LocalService old = localById.get(serviceId);
    if (old == null) {
      throw new TRADEServiceNotFoundException("Service " + serviceId + " is not registered in"
          + " container " + containerName + "; look the service up again");
    }
    ServiceDescriptor o = old.descriptor();
    ServiceDescriptor d = new ServiceDescriptor(o.containerId(), o.containerName(), o.host(),
        o.serviceId(), o.name(), o.parameterNames(), o.parameterTypeNames(), o.returnTypeName(),
        new LinkedHashSet<>(groups), o.annotations(), o.genericReturnTypeName(),
        o.exceptionTypeNames(), o.parameterAnnotations());
    LocalService s = old.withDescriptor(d);
    localById = localById.with(s);
    for (List<LocalService> list : byProvider.values()) {
      list.replaceAll(x -> x == old ? s : x);
    }
    Map<Long, Entry> own = tables.get(containerId);
    Entry removed = own.get(serviceId);
    Entry added = new Entry(d, 0, s);
    own.put(serviceId, added);
    localVersion++;
    publish(List.of(added), removed == null ? List.of() : List.of(removed));
    return d;
  }

  /** Every provider registered here, in no particular order: a snapshot. */
  public synchronized List<Object> providers() {
    return new ArrayList<>(byProvider.keySet());
  }

  /** The services of {@code provider} registered here, or null when it is not registered. */
  public synchronized List<LocalService> servicesOf(Object provider) {
    List<LocalService> services = byProvider.get(provider);
    return services == null ? null : List.copyOf(services);
  }

  /** Removes every local service (used when the container closes). */
  public synchronized void deregisterAll() {
    List<LocalService> all = new ArrayList<>();
    byProvider.values().forEach(all::addAll);
    byProvider.clear();
    removeLocal(all);
  }

  private void removeLocal(List<LocalService> services) {
    Map<Long, Entry> own = tables.get(containerId);
    List<Entry> removed = new ArrayList<>(services.size());
    for (LocalService s : services) {
      s.deactivate();
      localById = localById.without(s.descriptor().serviceId());
      Entry e = own.remove(s.descriptor().serviceId());
      if (e != null) {
        removed.add(e);
      }
    }
    localVersion++;
    publish(List.of(), removed);
  }

  /** This container's own table and its version, consistent with each other. */
  public synchronized Table localTable() {
    List<ServiceDescriptor> services = new ArrayList<>();
    tables.get(containerId).values().forEach(e -> services.add(e.descriptor()));
    return new Table(containerId, localVersion, services);
  }

  /** The version of this container's own table (changes with every register and deregister). */
  public synchronized long localVersion() {
    return localVersion;
  }

  /** Every other container's table, to hand to a new neighbour. */
  public synchronized List<Table> remoteTables() {
    List<Table> result = new ArrayList<>();
    for (Map.Entry<String, Map<Long, Entry>> t : tables.entrySet()) {
      if (!t.getKey().equals(containerId)) {
        List<ServiceDescriptor> services = new ArrayList<>();
        t.getValue().values().forEach(e -> services.add(e.descriptor()));
        result.add(new Table(t.getKey(), versions.getOrDefault(t.getKey(), 0L), services));
      }
    }
    return result;
  }

  /**
   * Whether a table or delta of {@code owner} at {@code version} would change nothing: it is this
   * container's own, or not newer than the version known. Lets a receiver drop the copies a flood
   * brings over every link before it decodes them.
   */
  public synchronized boolean isStale(String owner, long version) {
    Long known = versions.get(owner);
    return owner.equals(containerId) || (known != null && known >= version);
  }

  /**
   * Replaces other containers' whole tables where newer than what is known, with one new snapshot
   * and one call of the listeners for all: a container that links to a large system lists the
   * tables of all its containers at once, and each snapshot copies them all.
   *
   * @param distances the distance of each table's owner
   * @return true when any was applied (the caller floods those on), false when all were stale
   */
  public synchronized boolean applyTables(List<Table> tables, Map<String, Integer> distances) {
    return applyTables(tables, distances, false);
  }

  /** As {@link #applyTables(List, Map)}, with a new snapshot even if none applies when {@code due}. */
  private boolean applyTables(List<Table> tables, Map<String, Integer> distances, boolean due) {
    List<Entry> added = new ArrayList<>();
    List<Entry> removed = new ArrayList<>();
    boolean changed = false;
    for (Table t : tables) {
      changed |= apply(t, distances.get(t.containerId()), added, removed);
    }
    if (changed) {
      publish(added, removed);
    } else if (due) {
      snapshot = Snapshot.of(this.tables);
    }
    return changed;
  }

  /** Applies {@code table} if newer, adding to {@code added} and {@code removed}; caller publishes. */
  private boolean apply(Table table, int distance, List<Entry> added, List<Entry> removed) {
    String owner = table.containerId();
    if (owner.equals(containerId)) {
      return false;
    }
    Long known = versions.get(owner);
    if (known != null && known >= table.version()) {
      return false;
    }
    versions.put(owner, table.version());
    Map<Long, Entry> old = tables.getOrDefault(owner, Map.of());
    Map<Long, Entry> fresh = new LinkedHashMap<>();
    for (ServiceDescriptor d : table.services()) {
      Entry e = old.get(d.serviceId());
      if (e == null) {
        e = new Entry(d, distance, null);
        added.add(e);
      }
      fresh.put(d.serviceId(), e.withDistance(distance));
    }
    for (Map.Entry<Long, Entry> e : old.entrySet()) {
      if (!fresh.containsKey(e.getKey())) {
        removed.add(e.getValue());
      }
    }
    tables.put(owner, fresh);
    return true;
  }

  /** What became of a delta. */
  public enum DeltaResult { APPLIED, STALE, GAP }

  /**
   * Applies another container's incremental change: only the next version in sequence applies; an
   * older one is stale, a newer one leaves a gap (the caller asks for the full table).
   */
  public synchronized DeltaResult applyDelta(String owner, long version, List<ServiceDescriptor> add,
      List<Long> remove, int distance) {
    if (owner.equals(containerId)) {
      return DeltaResult.STALE;
    }
    Long known = versions.get(owner);
    if (known != null && version <= known) {
      return DeltaResult.STALE;
    }
    if (known == null || version != known + 1) {
      return DeltaResult.GAP;
    }
    versions.put(owner, version);
    Map<Long, Entry> table = tables.computeIfAbsent(owner, k -> new LinkedHashMap<>());
    // Removals first: a service whose groups changed is removed and added with the same id.
    List<Entry> removed = new ArrayList<>();
    for (Long id : remove) {
      Entry e = table.remove(id);
      if (e != null) {
        removed.add(e);
      }
    }
    List<Entry> added = new ArrayList<>();
    for (ServiceDescriptor d : add) {
      Entry e = new Entry(d, distance, null);
      table.put(d.serviceId(), e);
      added.add(e);
    }
    publish(added, removed);
    return DeltaResult.APPLIED;
  }

  /**
   * Forgets a container that left or became unreachable; its services go away everywhere here.
   *
   * @return its table as it was, or null when none was known
   */
  public synchronized Table removeContainer(String owner) {
    if (owner.equals(containerId)) {
      return null;
    }
    Long version = versions.remove(owner);
    Map<Long, Entry> table = tables.remove(owner);
    if (table == null) {
      return null;
    }
    List<ServiceDescriptor> services = new ArrayList<>();
    table.values().forEach(e -> services.add(e.descriptor()));
    if (!table.isEmpty()) {
      publish(List.of(), new ArrayList<>(table.values()));
    }
    for (Listener l : listeners) {
      l.containerLeft(owner);
    }
    return new Table(owner, version == null ? 0L : version, services);
  }

  /** Containers whose tables are known here, this one excluded. */
  public synchronized List<String> remoteContainers() {
    List<String> result = new ArrayList<>(tables.keySet());
    result.remove(containerId);
    return result;
  }

  /**
   * Follows newly computed routes in one step: moves the containers in {@code moved} to their new
   * distances (reorders lookups; no joined/left events; others keep theirs) and applies
   * {@code tables} as {@link #applyTables} does. One snapshot serves both: routing does both after
   * most computations while a system grows, and each snapshot copies every entry.
   *
   * @param distances the distance of each table's owner
   */
  public synchronized void followRoutes(Map<String, Integer> moved, List<Table> tables,
      Map<String, Integer> distances) {
    boolean changed = false;
    for (Map.Entry<String, Integer> owner : moved.entrySet()) {
      Map<Long, Entry> table = this.tables.get(owner.getKey());
      if (table == null || owner.getKey().equals(containerId)) {
        continue;
      }
      int d = owner.getValue();
      for (Map.Entry<Long, Entry> e : table.entrySet()) {
        Entry m = e.getValue().withDistance(d);
        if (m != e.getValue()) {
          e.setValue(m);
          changed = true;
        }
      }
    }
    applyTables(tables, distances, changed);
  }

  /**
   * Runs {@code action} while no change can happen: listeners are told of changes under the same
   * lock, so an action that reads and subscribes misses nothing and sees nothing twice.
   */
  public synchronized void runLocked(Runnable action) {
    action.run();
  }

  /** The active local service with this id, or null. Lock-free. */
  public LocalService local(long serviceId) {
    return localById.get(serviceId);
  }

  /** The services matching {@code query}, in preference order; {@code name} narrows the scan. */
  public List<Entry> find(String name, Query query) {
    Snapshot s = snapshot;
    List<Entry> candidates = name == null ? s.ordered() : s.byName().getOrDefault(name, List.of());
    List<Entry> result = new ArrayList<>();
    for (Entry e : candidates) {
      if (query.matches(e, containerId, host)) {
        result.add(e);
      }
    }
    return result;
  }

  /** The first match in preference order, or null. */
  public Entry findFirst(String name, Query query) {
    Snapshot s = snapshot;
    List<Entry> candidates = name == null ? s.ordered() : s.byName().getOrDefault(name, List.of());
    for (Entry e : candidates) {
      if (query.matches(e, containerId, host)) {
        return e;
      }
    }
    return null;
  }

  /** Every known entry, in preference order. */
  public List<Entry> all() {
    return snapshot.ordered();
  }

  /**
   * An object replaced at every change of the known services, to compare by identity: while it is
   * the same, every entry found earlier is still known. Lock-free.
   */
  public Object generation() {
    return snapshot;
  }

  /** The entry of a known service, or null when it is not (or no longer) known here. */
  public Entry entry(ServiceDescriptor d) {
    return snapshot.entry(d);
  }

  private ServiceDescriptor descriptor(String name, List<String> names, List<String> types,
      String ret, Collection<String> groups, List<Annotation> annotations, String genericRet,
      List<String> exceptions, List<List<Annotation>> parameterAnnotations) {
    return new ServiceDescriptor(containerId, containerName, host, nextServiceId.getAndIncrement(),
        name, names, types, ret, new LinkedHashSet<>(groups), annotations, genericRet, exceptions,
        parameterAnnotations);
  }

  private void publish(List<Entry> added, List<Entry> removed) {
    snapshot = Snapshot.of(tables);
    for (Listener l : listeners) {
      l.changed(added, removed);
    }
  }

  private static String describe(Object provider) {
    return provider.getClass().getName() + "@" + Integer.toHexString(System.identityHashCode(provider));
  }
}
