package dev.trade.internal.hooks;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemServices;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;

/**
 * The requester's side of hooks, behind the static API: it calls the hook service of the container
 * that provides each target, like any service; it never reaches around the call path.
 *
 * <p>A set hook ({@link #addSet}) lives here: this client adds a hook, tagged with the set's id,
 * on every service matching the set's constraints now, and then on each one that joins anywhere
 * (told by this container's registry; the hook reaches the new service's container one call
 * later). Removing the set removes its hooks everywhere. A set ends by itself when its wrapper
 * leaves (every container removes that wrapper's hooks then). Safe for concurrent use.
 */
public final class HookClient implements Registry.Listener {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");

  /** A set hook made here. */
  private record SetHook(String id, Kind kind, ServiceDescriptor wrapper, Query query) {
    boolean covers(Entry e) {
      return !e.descriptor().sameService(wrapper);
    }
  }

  private final Registry registry;
  private final ServiceCaller caller;
  private final InfoBinding infos;
  private final Function<Object, Query> queries;
  private final String requester;
  private final List<SetHook> sets = new CopyOnWriteArrayList<>();
  private final AtomicLong nextSet = new AtomicLong();
  private ExecutorService joins; // Guarded by this: adds the hooks of sets on services that join.
  private boolean closed; // Guarded by this.

  /**
   * @param queries turns a {@code TRADEServiceConstraints} into a query (null for anything else)
   * @param requester this container's name, which the hook services list
   */
  public HookClient(Registry registry, ServiceCaller caller, InfoBinding infos,
      Function<Object, Query> queries, String requester) {
    this.registry = registry;
    this.caller = caller;
    this.infos = infos;
    this.queries = queries;
    this.requester = requester;
    registry.addListener(this);
  }

  /**
   * Adds a hook at the container that provides {@code target}.
   *
   * @return the hook's id
   */
  public String add(Kind kind, Object wrapper, Object target) throws TRADEException {
    return add(kind, wrapper, describe(target, "target"), "");
  }

  private String add(Kind kind, Object wrapper, ServiceDescriptor target, String set)
      throws TRADEException {
    Objects.requireNonNull(wrapper, "wrapper == null");
    return SystemServices.call(registry, caller, target.containerId(), "addHook", String.class,
        kind.label(), wrapper, infos.bind(target), set, requester);
  }

  /**
   * Removes the hook of that kind, wrapper and target.
   *
   * @return whether there was one
   */
  public boolean remove(Kind kind, Object wrapper, Object target) throws TRADEException {
    Objects.requireNonNull(wrapper, "wrapper == null");
    ServiceDescriptor t = describe(target, "target");
    return SystemServices.call(registry, caller, t.containerId(), "removeHook", Boolean.class,
        kind.label(), wrapper, target);
  }

  /**
   * Hooks {@code wrapper} on every service matching {@code constraints} but the wrapper itself,
   * now and as services join. A service that refuses the hook (one of the reserved group, where
   * that is not allowed) or cannot be reached is logged and left out.
   *
   * @return how many services it covers now
   * @throws TRADEBadArgumentsException if {@code constraints} are not constraints
   */
  public int addSet(Kind kind, Object wrapper, Object constraints) throws TRADEException {
    return addSet(kind, describe(wrapper, "wrapper"), query(constraints));
  }

  /** As {@link #addSet(Kind, Object, Object)}, with the wrapper and targets resolved. */
  int addSet(Kind kind, ServiceDescriptor w, Query targets) {
    SetHook s = new SetHook(registry.containerId() + ":set" + nextSet.incrementAndGet(), kind, w,
        targets);
    // Listed before the first lookup: a service joining meanwhile is hooked twice at worst, and
    // adding a hook twice adds it once.
    sets.add(s);
    int n = 0;
    for (Entry e : registry.find(null, s.query)) {
      if (s.covers(e) && install(s, e.descriptor())) {
        n++;
      }
    }
    return n;
  }

  /**
   * Removes the set hook of that kind, wrapper and constraints made here, and its hooks everywhere.
   *
   * @return whether there was one
   */
  public boolean removeSet(Kind kind, Object wrapper, Object constraints) throws TRADEException {
    return removeSet(kind, describe(wrapper, "wrapper"), query(constraints));
  }

  /** As {@link #removeSet(Kind, Object, Object)}, with the wrapper and targets resolved. */
  boolean removeSet(Kind kind, ServiceDescriptor w, Query q) {
    boolean found = false;
    for (SetHook s : sets) {
      if (s.kind == kind && s.wrapper.sameService(w) && s.query.equals(q) && sets.remove(s)) {
        found = true;
        for (ServiceDescriptor d : SystemServices.everywhere(registry, "removeHooks")) {
          try {
            SystemServices.call(caller, d, Integer.class, s.id);
          } catch (TRADEException e) {
            LOG.log(Level.DEBUG, "set hook {0}: removing its hooks in container {1} failed: {2}",
                s.id, d.containerName(), e.getMessage());
          }
        }
      }
    }
    return found;
  }

  /** Called under the registry's lock: only records and hands work to this client's thread. */
  @Override
  public void changed(List<Entry> added, List<Entry> removed) {
    if (sets.isEmpty()) {
      return;
    }
    for (Entry e : removed) {
      sets.removeIf(s -> s.wrapper.sameService(e.descriptor()));
    }
    for (Entry e : added) {
      for (SetHook s : sets) {
        if (s.covers(e) && s.query.matches(e, registry.containerId(), registry.host())) {
          ServiceDescriptor d = e.descriptor();
          later(() -> {
            if (sets.contains(s)) {
              install(s, d);
            }
          });
        }
      }
    }
  }

  /** Stops following joins; the hooks stay where they are until their wrapper leaves. */
  public void close() {
    registry.removeListener(this);
    synchronized (this) {
      closed = true;
      if (joins != null) {
        joins.shutdownNow();
      }
    }
  }

  private boolean install(SetHook s, ServiceDescriptor target) {
    try {
      add(s.kind, infos.bind(s.wrapper), target, s.id);
      return true;
    } catch (TRADEException e) {
      LOG.log(Level.WARNING, "set hook {0} ({1} {2}) left out {3}: {4}", s.id, s.kind.label(),
          Hook.where(s.wrapper), Hook.where(target), e.getMessage());
      return false;
    }
  }

  private synchronized void later(Runnable task) {
    if (closed) {
      return;
    }
    if (joins == null) {
      joins = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "trade-hooks-joins-" + requester);
        t.setDaemon(true);
        return t;
      });
    }
    try {
      joins.execute(task);
    } catch (RejectedExecutionException closing) {
      // The container is closing: no hook is wanted any more.
    }
  }

  private Query query(Object constraints) throws TRADEBadArgumentsException {
    Query q = queries.apply(constraints);
    if (q == null) {
      throw new TRADEBadArgumentsException("A set hook's targets must be TRADEServiceConstraints,"
          + " not " + constraints.getClass().getName());
    }
    return q;
  }

  private ServiceDescriptor describe(Object info, String what) throws TRADEBadArgumentsException {
    ServiceDescriptor d = info == null ? null : infos.describe(info);
    if (d == null) {
      throw new TRADEBadArgumentsException("A hook's " + what + " must be a TRADEServiceInfo, not "
          + (info == null ? "null" : info.getClass().getName()));
    }
    return d;
  }
}
