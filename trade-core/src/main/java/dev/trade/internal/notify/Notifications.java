package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemServices;
import dev.trade.internal.time.Scheduler;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Function;

/**
 * The notifications that run in this container: the engine behind {@link NotificationService}.
 *
 * <p>Joined and left follow the changes of the replicated registry (every container sees the same
 * changes, so no extra messages travel); their events are queued, under the registry's lock, to
 * one ordered event queue, so each event reaches each matching request once and in the order the
 * changes happened. Timed types are due on the {@link Scheduler}; a due delivery runs on the
 * delivery pool, and a delivery still running when the next is due makes that one skipped and
 * counted. Every callback, condition and service is called as a service, through the
 * {@link ServiceCaller} (so through the providing container's host chain). A failure is logged
 * with its context and counted and does not end the notification; the notification ends when it
 * is cancelled, when it fired for the last time, or when its callback or service leaves (logged
 * once with the reason). No network or registry thread ever runs a callback.
 *
 * <p>This class is safe for concurrent use.
 */
public final class Notifications implements Registry.Listener {
  private static final Logger LOG = System.getLogger("dev.trade.notify");
  /** How many ended notifications {@link #ended()} keeps, newest first. */
  static final int ENDED_KEPT = 64;
  /**
   * How long a request waits for its callback and service to be known here: a listener the
   * requester registered just before asking, or a service of a third container, may reach this
   * container's table a moment after the request.
   */
  static final long KNOWN_WAIT_MS = 5000;

  private final Registry registry;
  private final ServiceCaller caller;
  private final InfoBinding infos;
  private final Function<Object, Query> queries;
  private final Scheduler scheduler;
  private final Executor deliveries;
  private final Executor events;
  private final List<ExecutorService> owned = new ArrayList<>(); // Guarded by itself.
  private final Map<String, Live> live = new ConcurrentHashMap<>();
  private final AtomicLong nextId = new AtomicLong();
  private final Deque<Map<String, Object>> ended = new ArrayDeque<>(); // Guarded by itself.
  private volatile boolean closed;
  /** Notified when services are added to the registry: requests wait on it for theirs. */
  private final Object added = new Object();

  /**
   * Notifications on the container's clock and timer; their threads start with the first delivery.
   *
   * @param scheduler the container's (closed by the container, not here)
   * @param caller calls callbacks, conditions and services (this container)
   * @param infos binds the {@code TRADEServiceInfo} handed to joined and left callbacks
   * @param queries turns joined and left's argument into a query, or null when it is of another kind
   */
  public Notifications(Registry registry, ServiceCaller caller, InfoBinding infos,
      Function<Object, Query> queries, Scheduler scheduler, String name) {
    this(registry, caller, infos, queries, scheduler, null, null, name);
  }

  /** With a scheduler and executors of the test's (null executors: the container's own). */
  Notifications(Registry registry, ServiceCaller caller, InfoBinding infos,
      Function<Object, Query> queries, Scheduler scheduler, Executor deliveries, Executor events,
      String name) {
    this.registry = registry;
    this.caller = caller;
    this.infos = infos;
    this.queries = queries;
    this.scheduler = scheduler;
    this.deliveries = deliveries != null ? deliveries
        : lazily(() -> Executors.newCachedThreadPool(threads("trade-notify-" + name + "-")));
    this.events = events != null ? events
        : lazily(() -> Executors.newSingleThreadExecutor(threads("trade-notify-events-" + name)));
    registry.addListener(this);
  }

  /**
   * Starts a notification.
   *
   * @return its id, unique in the system: this container's id, ':', a number
   * @throws TRADEBadArgumentsException the request is bad (see {@link Spec#parse}); nothing started
   * @throws TRADEServiceUnavailableException the callback or service is not known here (any more)
   */
  String request(String type, Object argument, List<ServiceDescriptor> services,
      ServiceDescriptor callback, String requester) throws TRADEException {
    Live l = newLive(type, argument, services, callback, requester);
    start(l, false);
    return l.id;
  }

  /**
   * A joined notification that also delivers, at once, every service matching now: one atomic
   * step with the registry's changes, so no service is missed or delivered twice.
   *
   * @return the id, and the services matching now
   */
  Map.Entry<String, List<ServiceDescriptor>> requestNowOrWhenJoined(Object constraints,
      ServiceDescriptor callback, String requester) throws TRADEException {
    Live l = newLive("joined", constraints, List.of(), callback, requester);
    return Map.entry(l.id, start(l, true));
  }

  private Live newLive(String type, Object argument, List<ServiceDescriptor> services,
      ServiceDescriptor callback, String requester) throws TRADEBadArgumentsException {
    if (closed) {
      throw new IllegalStateException("notifications of " + registry.containerId() + " are closed");
    }
    Spec spec = Spec.parse(type, argument, services, callback, requester, queries,
        scheduler.nanoTime(), scheduler.instant());
    return new Live(registry.containerId() + ":" + nextId.incrementAndGet(), spec);
  }

  /** Makes {@code l} live, checking under the registry's lock that what it uses is there. */
  private List<ServiceDescriptor> start(Live l, boolean deliverMatches) throws TRADEException {
    awaitKnown(l);
    TRADEException[] missing = new TRADEException[1];
    List<ServiceDescriptor> matches = new ArrayList<>();
    registry.runLocked(() -> {
      for (ServiceDescriptor d : l.spec.service() == null ? List.of(l.spec.callback())
          : List.of(l.spec.callback(), l.spec.service())) {
        if (registry.entry(d) == null) {
          missing[0] = new TRADEServiceUnavailableException("Service not available: " + Live.where(d)
              + " is not known in container " + registry.containerId() + " (waited "
              + KNOWN_WAIT_MS + " ms for it)");
          return;
        }
      }
      live.put(l.id, l);
      if (deliverMatches) {
        for (Entry e : registry.find(null, l.spec.query())) {
          matches.add(e.descriptor());
          enqueue(l, e.descriptor());
        }
      }
    });
    if (missing[0] != null) {
      throw missing[0];
    }
    if (l.spec.timing() != null) {
      try {
        schedule(l, l.firstWake());
      } catch (RejectedExecutionException closing) {
        live.remove(l.id);
        throw new IllegalStateException("notifications of " + registry.containerId() + " are closed");
      }
    }
    LOG.log(Level.DEBUG, "notification {0} ({1}) requested by {2}, callback {3}", l.id,
        l.spec.kind().label(), l.spec.requester(), Live.where(l.spec.callback()));
    return matches;
  }

  /** Waits up to {@link #KNOWN_WAIT_MS} for {@code l}'s callback and service to be known here. */
  private void awaitKnown(Live l) throws TRADEException {
    long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(KNOWN_WAIT_MS);
    synchronized (added) {
      while (registry.entry(l.spec.callback()) == null
          || (l.spec.service() != null && registry.entry(l.spec.service()) == null)) {
        long left = deadline - System.nanoTime();
        if (left <= 0 || closed) {
          return; // start() refuses it, naming what is missing
        }
        try {
          TimeUnit.NANOSECONDS.timedWait(added, left);
        } catch (InterruptedException e) {
          Thread.currentThread().interrupt();
          throw new TRADEException("Interrupted while waiting for " + Live.where(l.spec.callback())
              + " to be known");
        }
      }
    }
  }

  /**
   * Cancels a notification of this container.
   *
   * @return whether it was live
   */
  boolean cancel(String id) {
    Live l = live.get(id);
    return l != null && end(l, "cancelled", Level.DEBUG);
  }

  /** The live notifications, as docs/notifications.md describes them. */
  List<Map<String, Object>> list() {
    long now = scheduler.nanoTime();
    Instant at = scheduler.instant();
    List<Map<String, Object>> result = new ArrayList<>();
    for (Live l : live.values()) {
      result.add(l.describe(now, at));
    }
    result.sort((a, b) -> ((String) a.get("id")).compareTo((String) b.get("id")));
    return result;
  }

  /** The last {@value #ENDED_KEPT} notifications that ended, newest first, with their reasons. */
  List<Map<String, Object>> ended() {
    synchronized (ended) {
      return new ArrayList<>(ended);
    }
  }

  /** A live notification by id (for tests), or null. */
  Live live(String id) {
    return live.get(id);
  }

  @Override
  public void changed(List<Entry> added, List<Entry> removed) {
    if (closed) {
      return;
    }
    if (!added.isEmpty()) {
      synchronized (this.added) {
        this.added.notifyAll();
      }
    }
    for (Live l : live.values()) {
      Kind k = l.spec.kind();
      if (k == Kind.JOINED || k == Kind.LEFT) {
        for (Entry e : k == Kind.JOINED ? added : removed) {
          if (l.spec.query().matches(e, registry.containerId(), registry.host())) {
            enqueue(l, e.descriptor());
          }
        }
      }
      for (Entry e : removed) {
        if (l.uses(e.descriptor())) {
          ServiceDescriptor d = e.descriptor();
          String which = l.spec.callback().sameService(d) ? "callback" : "service";
          runOn(events, () -> end(l, "its " + which + " " + Live.where(d) + " left", Level.INFO));
        }
      }
    }
  }

  /** Stops: nothing is delivered any more and no notification of this container lives on. */
  public void close() {
    closed = true;
    registry.removeListener(this);
    // The timer is the container's and outlives this: what is pending on it is cancelled here.
    live.values().forEach(l -> l.end("closed"));
    live.clear();
    synchronized (owned) {
      owned.forEach(ExecutorService::shutdownNow);
    }
  }

  private void enqueue(Live l, ServiceDescriptor d) {
    runOn(events, () -> deliverEvent(l, d));
  }

  private void schedule(Live l, long at) {
    l.timer(scheduler.schedule(() -> due(l), at));
  }

  /**
   * The timer's task, a lead before a due time: decides, schedules its next wake-up, hands the
   * delivery to the pool, where it waits for its due time. The timer never waits for a delivery.
   */
  private void due(Live l) {
    Live.Step step = l.due(scheduler.nanoTime());
    if (step.wakeNanos() >= 0) {
      try {
        schedule(l, step.wakeNanos());
      } catch (RejectedExecutionException closing) {
        return;
      }
    }
    if (step.deliver()) {
      runOn(deliveries, new Delivery(l, step.dueNanos()));
    }
  }

  /** A timed delivery handed to the pool before its due time, which it waits for first. */
  final class Delivery implements Runnable {
    final Live live;
    final long dueNanos;

    Delivery(Live live, long dueNanos) {
      this.live = live;
      this.dueNanos = dueNanos;
    }

    @Override
    public void run() {
      try {
        scheduler.sleepUntil(dueNanos);
      } catch (InterruptedException closing) {
        finished(live, false, null);
        return;
      }
      if (live.ended()) {
        finished(live, false, null); // cancelled while it waited
        return;
      }
      deliver(live);
    }
  }

  private void deliverEvent(Live l, ServiceDescriptor d) {
    if (!l.startEvent()) {
      return; // cancelled while the event waited
    }
    String error = callBack(l, new Object[] {infos.bind(d)});
    finished(l, error == null, error);
  }

  /** One delivery of a timed type, on the delivery pool. */
  void deliver(Live l) {
    Spec s = l.spec;
    Object result = null;
    TRADEException failure = null;
    if (s.service() != null) {
      try {
        result = caller.call(s.service(), Object.class, s.serviceArgs(), 0);
      } catch (TRADEException e) {
        failure = e;
      }
    }
    if (failure != null && gone(l, s.service())) {
      finished(l, false, null);
      return;
    }
    String error = failure == null ? null : "service " + Live.where(s.service()) + " failed: "
        + failure.getMessage();
    boolean call;
    Object[] args;
    if (s.kind().isCondition()) {
      call = Boolean.TRUE.equals(result);
      args = new Object[0];
    } else {
      switch (s.shape()) {
        case NONE:
          call = true;
          args = new Object[0];
          break;
        case VALUE:
          call = failure == null;
          args = new Object[] {result};
          break;
        default:
          call = true;
          args = new Object[] {result, failure};
      }
    }
    String callbackError = call ? callBack(l, args) : null;
    finished(l, call && callbackError == null, callbackError != null ? callbackError : error);
    boolean last = s.timing().periodNanos() == 0 || (s.kind() == Kind.WHEN && call);
    if (last) {
      end(l, s.kind() == Kind.WHEN ? "its condition became true" : "it was due for the last time",
          Level.DEBUG);
    }
  }

  /** Calls the callback; returns what failed, or null. */
  private String callBack(Live l, Object[] args) {
    try {
      caller.call(l.spec.callback(), Object.class, args, 0);
      return null;
    } catch (TRADEException e) {
      if (gone(l, l.spec.callback())) {
        return null;
      }
      return "callback " + Live.where(l.spec.callback()) + " failed: " + e.getMessage();
    }
  }

  /** Whether {@code d} left: then {@code l} ends (the registry's listener may not have told yet). */
  private boolean gone(Live l, ServiceDescriptor d) {
    if (registry.entry(d) != null) {
      return false;
    }
    String which = l.spec.callback().sameService(d) ? "callback" : "service";
    end(l, "its " + which + " " + Live.where(d) + " left", Level.INFO);
    return true;
  }

  private void finished(Live l, boolean calledBack, String error) {
    if (l.finished(calledBack, error) && !l.ended()) {
      LOG.log(Level.WARNING, "notification {0} ({1}, requested by {2}): {3}; it goes on",
          l.id, l.spec.kind().label(), l.spec.requester(), error);
    } else if (error != null) {
      LOG.log(Level.DEBUG, "notification {0}: {1}", l.id, error);
    }
  }

  private boolean end(Live l, String reason, Level level) {
    if (!l.end(reason)) {
      return false;
    }
    live.remove(l.id, l);
    Map<String, Object> last = l.describe(scheduler.nanoTime(), scheduler.instant());
    synchronized (ended) {
      ended.addFirst(last);
      if (ended.size() > ENDED_KEPT) {
        ended.removeLast();
      }
    }
    LOG.log(level, "notification {0} ({1}, requested by {2}, callback {3}) ended: {4}", l.id,
        l.spec.kind().label(), l.spec.requester(), Live.where(l.spec.callback()), reason);
    runOn(deliveries, () -> tellEnded(l, reason));
    return true;
  }

  /**
   * Tells the callback's container that {@code l} ended, so that a requester that keeps its
   * listener-form requests (its callbacks are its own listeners' services) forgets it. On the
   * delivery pool: a slow or gone container does not hold up whoever ended it.
   */
  private void tellEnded(Live l, String reason) {
    try {
      SystemServices.call(registry, caller, l.spec.callback().containerId(), "notificationEnded",
          Object.class, l.id, reason);
    } catch (TRADEException | RuntimeException e) {
      // Gone, or a container that keeps no such requests: nothing is left to forget there.
      LOG.log(Level.DEBUG, "notification {0}: its end not told to {1}: {2}", l.id,
          l.spec.callback().containerName(), e.getMessage());
    }
  }

  private static void runOn(Executor executor, Runnable task) {
    try {
      executor.execute(task);
    } catch (RejectedExecutionException closed) {
      // The container is closing: nobody is left to tell.
    }
  }

  private Executor lazily(java.util.function.Supplier<ExecutorService> factory) {
    Object[] holder = new Object[1];
    return task -> {
      ExecutorService e;
      synchronized (owned) {
        if (closed) {
          throw new RejectedExecutionException("closed");
        }
        if (holder[0] == null) {
          holder[0] = factory.get();
          owned.add((ExecutorService) holder[0]);
        }
        e = (ExecutorService) holder[0];
      }
      e.execute(task);
    };
  }

  private static java.util.concurrent.ThreadFactory threads(String prefix) {
    AtomicLong n = new AtomicLong();
    return r -> {
      Thread t = new Thread(r, prefix.endsWith("-") ? prefix + n.incrementAndGet() : prefix);
      t.setDaemon(true);
      return t;
    };
  }
}
