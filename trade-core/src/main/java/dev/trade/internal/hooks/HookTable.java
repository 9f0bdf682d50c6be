package dev.trade.internal.hooks;

import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;

/**
 * The hooks installed in this container, by target. Changes (rare) take this table's lock and
 * publish a new immutable map from target service id to its hooks in order of addition; the host
 * chain reads that map without locking, so a call never resolves anything but one map lookup.
 *
 * <p>It follows the registry: a hook whose wrapper or target left is removed, and the wrapper's
 * leaving is logged once. This class is safe for concurrent use.
 */
final class HookTable implements Registry.Listener {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");

  /** The hooks of one target, each array in order of addition. Immutable. */
  record OnTarget(Hook[] before, Hook[] after, boolean timed) {}

  private final String containerId;
  // Guarded by this: every hook, in order of addition.
  private final List<Hook> all = new ArrayList<>();
  private long nextId; // Guarded by this.
  /** The map of a table without hooks, compared by identity on every call. */
  private static final Map<Long, OnTarget> NONE = Map.of();
  // Written under this' lock, read lock-free by every call.
  private volatile Map<Long, OnTarget> byTarget = NONE;

  /** Notified when services are added to the registry: {@link #awaitKnown} waits on it. */
  private final Object known = new Object();

  HookTable(String containerId) {
    this.containerId = containerId;
  }

  /**
   * Waits up to {@code millis} for {@code d} to be known in {@code registry}: a wrapper its
   * requester registered just before asking may reach this container's table a moment after the
   * request (from a third container, by another path).
   *
   * @return whether it is known
   */
  boolean awaitKnown(Registry registry, ServiceDescriptor d, long millis)
      throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
    synchronized (known) {
      while (registry.entry(d) == null) {
        long left = deadline - System.nanoTime();
        if (left <= 0) {
          return false;
        }
        TimeUnit.NANOSECONDS.timedWait(known, left);
      }
      return true;
    }
  }

  /** The hooks of the local service {@code serviceId}, or null if it has none. */
  OnTarget of(long serviceId) {
    Map<Long, OnTarget> m = byTarget;
    return m == NONE ? null : m.get(serviceId);
  }

  /**
   * Adds a hook, or returns the one of the same kind, wrapper and target already there (adding
   * twice does not call the wrapper twice).
   */
  synchronized Hook add(Kind kind, ServiceDescriptor wrapper, ServiceDescriptor target,
      int parameters, String set, String requester) {
    for (Hook h : all) {
      if (h.same(kind, wrapper, target)) {
        return h;
      }
    }
    Hook h = new Hook(containerId + ":" + ++nextId, kind, wrapper, target, parameters, set,
        requester);
    all.add(h);
    publish();
    return h;
  }

  /** Removes the hook of that kind, wrapper and target; returns whether there was one. */
  synchronized boolean remove(Kind kind, ServiceDescriptor wrapper, ServiceDescriptor target) {
    return removeIf(h -> h.same(kind, wrapper, target)) > 0;
  }

  /** Removes the hooks of set {@code set}; returns how many. */
  synchronized int removeSet(String set) {
    return set.isEmpty() ? 0 : removeIf(h -> h.set.equals(set));
  }

  /** The hook with this id, or null. */
  synchronized Hook byId(String id) {
    for (Hook h : all) {
      if (h.id.equals(id)) {
        return h;
      }
    }
    return null;
  }

  /** Every hook, in order of addition. */
  synchronized List<Hook> all() {
    return new ArrayList<>(all);
  }

  private int removeIf(Predicate<Hook> which) {
    int before = all.size();
    all.removeIf(which);
    if (all.size() != before) {
      publish();
    }
    return before - all.size();
  }

  private void publish() {
    Map<Long, List<Hook>> before = new HashMap<>();
    Map<Long, List<Hook>> after = new HashMap<>();
    Set<Long> timed = new HashSet<>();
    for (Hook h : all) {
      if (h.parameters == 3) {
        timed.add(h.target.serviceId());
      }
      (h.kind == Kind.BEFORE ? before : after)
          .computeIfAbsent(h.target.serviceId(), k -> new ArrayList<>()).add(h);
    }
    Map<Long, OnTarget> m = new HashMap<>();
    for (Hook h : all) {
      long t = h.target.serviceId();
      m.computeIfAbsent(t, k -> new OnTarget(
          before.getOrDefault(k, List.of()).toArray(new Hook[0]),
          after.getOrDefault(k, List.of()).toArray(new Hook[0]), timed.contains(k)));
    }
    byTarget = m.isEmpty() ? NONE : Map.copyOf(m);
  }

  /** Called under the registry's lock: only this table's own state changes here. */
  @Override
  public void changed(List<Entry> added, List<Entry> removed) {
    if (!added.isEmpty()) {
      synchronized (known) {
        known.notifyAll();
      }
    }
    if (removed.isEmpty()) {
      return;
    }
    synchronized (this) {
      List<ServiceDescriptor> wrappersGone = new ArrayList<>();
      List<Hook> gone = new ArrayList<>();
      for (Hook h : all) {
        for (Entry e : removed) {
          ServiceDescriptor d = e.descriptor();
          if (h.wrapper.sameService(d) || h.target.sameService(d)) {
            gone.add(h);
            if (h.wrapper.sameService(d) && !wrappersGone.contains(d)) {
              wrappersGone.add(d);
            }
            break;
          }
        }
      }
      if (gone.isEmpty()) {
        return;
      }
      all.removeAll(gone);
      publish();
      for (ServiceDescriptor w : wrappersGone) {
        int n = 0;
        for (Hook h : gone) {
          n += h.wrapper.sameService(w) ? 1 : 0;
        }
        LOG.log(Level.INFO, "removed {0} hook{1} of wrapper {2} in container {3}: the wrapper left",
            n, n == 1 ? "" : "s", Hook.where(w), containerId);
      }
    }
  }
}
