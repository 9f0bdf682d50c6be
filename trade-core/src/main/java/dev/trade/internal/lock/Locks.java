package dev.trade.internal.lock;

import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.system.SystemGroup;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.function.LongSupplier;

/**
 * Locks in one container, assembled: the lease table of its services, the host chain's lock link,
 * the lock service it registers in the reserved group and the client behind the static API. Safe
 * for concurrent use.
 */
public final class Locks {
  private static final Logger LOG = System.getLogger("dev.trade.lock");

  /** Context key: the id of the lock a call is made under (docs/protocol.md, "Call context"). */
  public static final String LOCK = "trade.lock";
  /** Context key: the fencing token of that lock for the called service, in decimal. */
  public static final String TOKEN = "trade.lock.token";
  /** Context key: {@code true} when a call to a locked service waits within its deadline. */
  public static final String WAIT = "trade.lock.wait";

  static final Query SYSTEM = new Query(null, null, null, Set.of(SystemGroup.NAME), Set.of(),
      false, null, null, Set.of(), List.of(), List.of());

  private final Registry registry;
  private final LeaseTable table;
  private final LockLink link;
  private final LockService service;
  private final LockClient client;

  /**
   * @param lease how long a lease lasts without renewal (FAILURETIMEOUT): a lock whose owner died
   *     or was cut off is free that long after its last renewal
   * @param callTimeout the default deadline of calls (CALLTIMEOUT), added to a lock request's wait
   */
  public Locks(Registry registry, ServiceCaller caller, InfoBinding infos, Duration lease,
      Duration callTimeout, String name) {
    this(registry, caller, infos, lease, callTimeout, name, System::nanoTime,
        System::currentTimeMillis);
  }

  Locks(Registry registry, ServiceCaller caller, InfoBinding infos, Duration lease,
      Duration callTimeout, String name, LongSupplier clock, LongSupplier wall) {
    this.registry = registry;
    this.table = new LeaseTable(lease.toNanos());
    Names names = new Names(name);
    this.link = new LockLink(table, clock, names::describe);
    this.service = new LockService(table, registry, infos, clock, wall, names);
    this.client = new LockClient(registry, caller, lease.toNanos(), callTimeout.toNanos(), name);
    registry.addListener(new Registry.Listener() {
      @Override
      public void changed(List<Entry> added, List<Entry> removed) {
        for (Entry e : removed) {
          if (e.local() != null) {
            table.drop(e.descriptor().serviceId());
          }
        }
        client.removed(removed);
      }

      @Override
      public void containerLeft(String containerId) {
        ownerLeft(containerId, clock.getAsLong());
      }
    });
  }

  /**
   * Container {@code containerId} left: the leases it owns here end at once (docs/locks.md,
   * "Leases and fencing"), rather than when their renewals stop.
   */
  void ownerLeft(String containerId, long now) {
    UUID owner;
    try {
      owner = UUID.fromString(containerId);
    } catch (IllegalArgumentException e) {
      return; // not a container id this table can hold leases for
    }
    int ended = table.ownerLeft(owner, now);
    if (ended > 0) {
      LOG.log(Level.INFO, "{0} lock(s) of container {1} ended here: the container left", ended,
          containerId);
    }
  }

  /** The host chain's lock link. */
  public CallLink link() {
    return link;
  }

  /** The system service to register in the reserved group. */
  public Object service() {
    return service;
  }

  /**
   * Makes calls to {@code services} (this container's system services that must know who asks:
   * the lock service's own, the notification service's) run with their invocation bound
   * ({@link dev.trade.internal.call.CurrentCall}), once they are registered.
   */
  public void bindCaller(List<LocalService> services) {
    long[] ids = new long[services.size()];
    for (int i = 0; i < ids.length; i++) {
      ids[i] = services.get(i).descriptor().serviceId();
    }
    link.bindCaller(ids);
  }

  /** The requester's side, behind the static API. */
  public LockClient client() {
    return client;
  }

  /** Stops renewing; the leases this container owns elsewhere end within a lease. */
  public void close() {
    client.close();
  }

  /** How holders and containers are named in errors and lists. */
  final class Names {
    private final String selfName;

    Names(String selfName) {
      this.selfName = selfName;
    }

    /** The name of container {@code id} as this container knows it, else its id. */
    String containerName(UUID id) {
      String text = id.toString();
      if (text.equals(registry.containerId())) {
        return selfName;
      }
      for (Entry e : registry.find("listLocks", SYSTEM)) {
        if (e.descriptor().containerId().equals(text)) {
          return e.descriptor().containerName();
        }
      }
      return text;
    }

    String describe(LeaseTable.Blocker b) {
      LocalService s = registry.local(b.service());
      String what = s == null ? "service " + b.service() : s.descriptor().signature();
      return what + (b.holding() ? " is held by" : " is awaited first by") + " lock " + b.claim().lock()
          + " of container " + containerName(b.claim().owner()) + " (" + b.claim().owner() + ")"
          + (b.claim().principal().isEmpty() ? "" : ", principal '" + b.claim().principal() + "'")
          + ", since " + Instant.ofEpochMilli(b.sinceMillis());
    }
  }
}
