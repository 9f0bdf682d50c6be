package dev.trade.internal.lock;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADELockedException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * The requester's side of locks, behind the static API: it takes a set of services in many
 * containers by calling their lock services, one container at a time in the order of their ids
 * (the services of one container at once, all or none), and releases what it took when one
 * refuses; it renews the leases of its locks, keeps each service's fencing token for calls under
 * the lock, and notices services that left. Locks are owned by this container: calls under them
 * are made from here. Safe for concurrent use.
 */
public final class LockClient {
  private static final Logger LOG = System.getLogger("dev.trade.lock");

  /** A lock taken from this container, until released. Safe for concurrent use. */
  public static final class Held {
    private final UUID id;
    private final List<ServiceDescriptor> services;
    private final Map<String, CallContext> contexts = new ConcurrentHashMap<>();
    private final Set<String> containers = ConcurrentHashMap.newKeySet();
    private final Set<String> dropped = ConcurrentHashMap.newKeySet();
    private volatile boolean released;

    Held(UUID id, List<ServiceDescriptor> services) {
      this.id = id;
      this.services = List.copyOf(services);
    }

    public UUID id() {
      return id;
    }

    /** Every service the lock was granted, in the order taken. */
    public List<ServiceDescriptor> services() {
      return services;
    }

    /** The services the lock lost since (they left, or their lease ended), in the order taken. */
    public List<ServiceDescriptor> dropped() {
      List<ServiceDescriptor> result = new ArrayList<>();
      for (ServiceDescriptor d : services) {
        if (dropped.contains(key(d))) {
          result.add(d);
        }
      }
      return result;
    }

    public boolean isReleased() {
      return released;
    }

    void granted(ServiceDescriptor d, long token) {
      contexts.put(key(d), CallContext.of(Map.of(Locks.LOCK, id.toString(),
          Locks.TOKEN, Long.toString(token))));
    }

    boolean holds(ServiceDescriptor d) {
      return contexts.containsKey(key(d));
    }

    @Override
    public String toString() {
      return "lock " + id + " " + services;
    }
  }

  private final Registry registry;
  private final ServiceCaller caller;
  private final long callTimeoutNanos;
  private final String name;
  private final Map<UUID, Held> mine = new ConcurrentHashMap<>();
  private ScheduledExecutorService renewer; // Guarded by this.
  private ScheduledFuture<?> nextRenewal; // Guarded by this.
  /**
   * The shortest lease a container granted a lock from here (their FAILURETIMEOUTs may differ from
   * ours): renewals go every third of it. Starts at our own and only shortens. Guarded by this.
   */
  private long shortestLeaseNanos;
  private boolean closed; // Guarded by this.

  LockClient(Registry registry, ServiceCaller caller, long leaseNanos, long callTimeoutNanos,
      String name) {
    this.registry = registry;
    this.caller = caller;
    this.shortestLeaseNanos = leaseNanos;
    this.callTimeoutNanos = callTimeoutNanos;
    this.name = name;
  }

  private static String key(ServiceDescriptor d) {
    return d.containerId() + "/" + d.serviceId();
  }

  /**
   * Locks {@code services}, all or none, waiting up to {@code waitNanos} for them to be free.
   *
   * @throws TRADELockedException if any is held by another lock (or awaited by an earlier request)
   *     when the wait ends; the message names that lock and its owner
   * @throws TRADEBadArgumentsException for an empty set or a system service
   * @throws TRADEServiceUnavailableException for a service not known here (any more)
   */
  public Held acquire(Collection<ServiceDescriptor> services, long waitNanos) throws TRADEException {
    if (services == null || services.isEmpty()) {
      throw new TRADEBadArgumentsException("A lock needs at least one service: the set to lock is"
          + " empty (no service matched?)");
    }
    TreeMap<String, TreeMap<Long, ServiceDescriptor>> byContainer = new TreeMap<>();
    for (ServiceDescriptor d : services) {
      if (d.groups().contains(SystemGroup.NAME)) {
        throw new TRADEBadArgumentsException("Service " + d.signature() + " is a system service"
            + " (group " + SystemGroup.NAME + "); system services cannot be locked");
      }
      if (registry.entry(d) == null) {
        throw CallErrors.gone(d, "not known in container " + name + "; nothing was locked");
      }
      byContainer.computeIfAbsent(d.containerId(), k -> new TreeMap<>()).put(d.serviceId(), d);
    }
    List<ServiceDescriptor> ordered = new ArrayList<>();
    byContainer.values().forEach(m -> ordered.addAll(m.values()));
    Held held = new Held(UUID.randomUUID(), ordered);
    long deadline = System.nanoTime() + Math.max(0, waitNanos);
    List<String> asked = new ArrayList<>();
    mine.put(held.id, held);
    try {
      startRenewing();
      for (Map.Entry<String, TreeMap<Long, ServiceDescriptor>> c : byContainer.entrySet()) {
        ServiceDescriptor lockService = lockService(c.getKey(), "lock");
        List<ServiceDescriptor> here = new ArrayList<>(c.getValue().values());
        long[] ids = new long[here.size()];
        for (int i = 0; i < ids.length; i++) {
          ids[i] = here.get(i).serviceId();
        }
        long left = waitNanos <= 0 ? 0 : Math.max(0, deadline - System.nanoTime());
        asked.add(c.getKey());
        Map<?, ?> r = callSystem(lockService, Map.class, left + callTimeoutNanos,
            held.id.toString(), ids, TimeUnit.NANOSECONDS.toMillis(left));
        if (!Boolean.TRUE.equals(r.get("granted"))) {
          throw new TRADELockedException("Lock not granted: " + r.get("reason")
              + (waitNanos > 0 ? " (waited " + TimeUnit.NANOSECONDS.toMillis(waitNanos) + " ms)"
              : "") + "; nothing was locked");
        }
        long[] tokens = (long[]) r.get("tokens");
        if (r.get("leaseMillis") instanceof Long ms && ms > 0) {
          leaseGranted(TimeUnit.MILLISECONDS.toNanos(ms));
        }
        held.containers.add(c.getKey());
        for (int i = 0; i < ids.length; i++) {
          held.granted(here.get(i), tokens[i]);
        }
      }
      return held;
    } catch (TRADEException | RuntimeException e) {
      mine.remove(held.id);
      held.released = true;
      Collections.reverse(asked);
      for (String c : asked) {
        releaseQuietly(c, held.id);
      }
      throw e;
    }
  }

  /** The lock {@code id} taken here and not released, or null. */
  public Held held(UUID id) {
    return id == null ? null : mine.get(id);
  }

  /**
   * Releases lock {@code id} in every container where it holds services. A container that cannot
   * be reached frees them when the lease ends there.
   *
   * @throws TRADEBadArgumentsException if no container holds a lock of that id (released
   *     already, its lease ended, or never granted)
   * @throws dev.trade.TRADENotAuthorizedException if another container owns it
   */
  public void release(UUID id) throws TRADEException {
    if (id == null) {
      throw new TRADEBadArgumentsException("releaseLock: the lock id is null");
    }
    Held held = mine.remove(id);
    if (held != null) {
      held.released = true;
      List<String> containers = new ArrayList<>(held.containers);
      containers.sort(Comparator.reverseOrder());
      for (String c : containers) {
        releaseQuietly(c, id);
      }
      return;
    }
    // Not taken here: the containers that hold it say whether it exists and whose it is.
    int released = 0;
    for (Entry e : registry.find("release", Locks.SYSTEM)) {
      try {
        released += callSystem(e.descriptor(), Integer.class, 0, id.toString());
      } catch (TRADEServiceUnavailableException | dev.trade.TRADETimeoutException gone) {
        // cannot hold it usably either: its lease there ends without renewal
      }
    }
    if (released == 0) {
      throw new TRADEBadArgumentsException("releaseLock: no lock " + id + " is held: it was"
          + " released already, its lease ended, or it was never granted");
    }
  }

  /**
   * The context of a call to {@code d} under lock {@code lock} (null: none), which waits for the
   * service to be free when {@code wait}.
   *
   * @throws TRADELockedException if the lock is not held from here or does not hold {@code d}
   */
  public CallContext context(ServiceDescriptor d, UUID lock, boolean wait) throws TRADEException {
    CallContext c = CallContext.EMPTY;
    if (lock != null) {
      Held held = mine.get(lock);
      if (held == null) {
        throw CallErrors.locked(d, "lock " + lock + " is not held by container " + name
            + " (released, its lease ended, never granted, or taken in another container: calls"
            + " under a lock are made from the container that took it)");
      }
      c = held.contexts.get(key(d));
      if (c == null) {
        throw CallErrors.locked(d, "lock " + lock + " does not hold it; it holds " + held.services);
      }
      // A dropped service that is known again (a partition healed) is asked all the same: its
      // container alone knows whether the lease is still this lock's, and refuses the old token
      // if it is not (fencing). One that is gone cannot be asked.
      if (held.dropped.contains(key(d)) && registry.entry(d) == null) {
        throw CallErrors.locked(d, "lock " + lock + " does not hold it any more (it left)");
      }
    }
    if (!wait) {
      return c;
    }
    Map<String, String> entries = new LinkedHashMap<>(c.entries());
    entries.put(Locks.WAIT, "true");
    return CallContext.of(entries);
  }

  /**
   * The leases and waiting requests of every container that answers, each container's by
   * service; see {@link LockService#listLocks()} for the keys.
   */
  public List<Map<String, Object>> list() throws TRADEException {
    List<Map<String, Object>> rows = new ArrayList<>();
    for (Entry e : registry.find("listLocks", Locks.SYSTEM)) {
      try {
        List<?> some = callSystem(e.descriptor(), List.class, 0);
        for (Object o : some) {
          @SuppressWarnings("unchecked")
          Map<String, Object> m = (Map<String, Object>) o;
          rows.add(m);
        }
      } catch (TRADEServiceUnavailableException | dev.trade.TRADETimeoutException gone) {
        LOG.log(Level.DEBUG, "locks of container {0} not listed: {1}",
            e.descriptor().containerName(), gone.getMessage());
      }
    }
    return rows;
  }

  /** Services that left: a lock that held one no longer does (the registry's listener). */
  void removed(List<Entry> removed) {
    if (mine.isEmpty()) {
      return;
    }
    for (Entry e : removed) {
      String k = key(e.descriptor());
      for (Held h : mine.values()) {
        if (h.contexts.containsKey(k)) {
          h.dropped.add(k);
        }
      }
    }
  }

  /** Renews the leases of every lock held from here, one asynchronous call per container. */
  void renew() {
    Map<String, List<Held>> byContainer = new TreeMap<>();
    for (Held h : mine.values()) {
      for (String c : h.containers) {
        byContainer.computeIfAbsent(c, k -> new ArrayList<>()).add(h);
      }
    }
    for (Map.Entry<String, List<Held>> c : byContainer.entrySet()) {
      ServiceDescriptor d = find(c.getKey(), "renew");
      if (d == null) {
        continue; // it left: its services were dropped by the registry's listener
      }
      List<String> ids = new ArrayList<>();
      for (Held h : c.getValue()) {
        ids.add(h.id.toString());
      }
      caller.callAsync(d, Map.class, new Object[] {ids}, Math.max(1, shortestLease() / 2))
          .whenComplete((r, failure) -> {
            if (r != null) {
              renewed(c.getKey(), c.getValue(), r);
            } else {
              LOG.log(Level.DEBUG, "renewing locks in container {0} failed: {1}",
                  d.containerName(), failure);
            }
          });
    }
  }

  /** A container's answer to a renewal: what it no longer holds is dropped. */
  private void renewed(String container, List<Held> asked, Map<?, ?> answer) {
    for (Held h : asked) {
      Object still = answer.get(h.id.toString());
      long[] ids = still instanceof long[] ? (long[]) still : new long[0];
      for (ServiceDescriptor d : h.services) {
        if (d.containerId().equals(container) && !contains(ids, d.serviceId())
            && mine.containsKey(h.id)) {
          if (h.dropped.add(key(d))) {
            LOG.log(Level.WARNING, "lock {0} lost {1} of container {2}: its lease there ended",
                h.id, d.signature(), d.containerName());
          }
        }
      }
    }
  }

  private static boolean contains(long[] ids, long id) {
    for (long x : ids) {
      if (x == id) {
        return true;
      }
    }
    return false;
  }

  private synchronized void startRenewing() {
    if (renewer == null && !closed) {
      renewer = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "trade-lock-renew-" + name);
        t.setDaemon(true);
        return t;
      });
      armRenewal();
    }
  }

  private synchronized long shortestLease() {
    return shortestLeaseNanos;
  }

  /** A container granted a lease of {@code nanos}: a shorter one than any so far renews sooner. */
  private synchronized void leaseGranted(long nanos) {
    if (nanos < shortestLeaseNanos) {
      shortestLeaseNanos = nanos;
      if (nextRenewal != null && nextRenewal.cancel(false)) {
        armRenewal();
      }
    }
  }

  private synchronized void armRenewal() {
    if (closed) {
      return;
    }
    nextRenewal = renewer.schedule(() -> {
      try {
        renew();
      } catch (RuntimeException e) {
        LOG.log(Level.WARNING, "renewing locks failed; trying again", e);
      }
      armRenewal();
    }, Math.max(1, shortestLeaseNanos / 3), TimeUnit.NANOSECONDS);
  }

  synchronized void close() {
    closed = true;
    if (renewer != null) {
      renewer.shutdownNow();
    }
  }

  private void releaseQuietly(String container, UUID id) {
    ServiceDescriptor d = find(container, "release");
    if (d == null) {
      return;
    }
    try {
      callSystem(d, Integer.class, 0, id.toString());
    } catch (TRADEException e) {
      LOG.log(Level.DEBUG, "lock {0} not released in container {1} ({2}); its lease ends there",
          id, d.containerName(), e.getMessage());
    }
  }

  private ServiceDescriptor find(String containerId, String method) {
    for (Entry e : registry.find(method, Locks.SYSTEM)) {
      if (e.descriptor().containerId().equals(containerId)) {
        return e.descriptor();
      }
    }
    return null;
  }

  private ServiceDescriptor lockService(String containerId, String method)
      throws TRADEServiceUnavailableException {
    ServiceDescriptor d = find(containerId, method);
    if (d == null) {
      throw new TRADEServiceUnavailableException(CallErrors.goneText("container " + containerId
          + " is not known here, or provides no " + method + " in group " + SystemGroup.NAME));
    }
    return d;
  }

  private <T> T callSystem(ServiceDescriptor d, Class<T> type, long timeoutNanos, Object... args)
      throws TRADEException {
    try {
      return caller.call(d, type, args, timeoutNanos);
    } catch (TRADEInvocationException e) {
      // Refused in the container it was sent to: its own typed error is the answer.
      if (e.getCause() instanceof TRADEException) {
        throw (TRADEException) e.getCause();
      }
      throw e;
    }
  }
}
