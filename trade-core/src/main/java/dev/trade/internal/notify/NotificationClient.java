package dev.trade.internal.notify;

import dev.trade.TRADEAccess;
import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.TRADETimeoutException;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import dev.trade.internal.system.SystemServices;
import java.lang.reflect.Method;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Function;

/**
 * The requester's side of notifications, behind the static API: it finds the notification
 * service of the container where a notification runs (the one providing {@code services[0]},
 * else this one) and calls it like any service; it never reaches around the call path.
 *
 * <p>The TRADE 1.1.1 forms name a listener object and its callback method: the callback is the
 * listener's {@code @TRADEService} of that name, and a listener not registered yet is registered
 * (in no group) for the purpose. This client remembers those requests while they live, so that
 * {@code cancel(listener, type, argument)} finds their ids, and deregisters a listener it
 * registered once its last such request is cancelled or ended. It forgets a request when it is
 * cancelled here, when the container that runs it says it ended ({@link #ended}: the engine tells
 * the callback's container, which is this one for these forms), or when that container leaves.
 * Safe for concurrent use.
 */
public final class NotificationClient implements Registry.Listener {
  /** How listeners are registered and deregistered (this container's user registration). */
  public interface Registrar {
    void register(Object listener) throws TRADEException;

    /** Registers one of the middleware's own listeners, in the reserved group. */
    void registerSystem(Object listener) throws TRADEException;

    void deregister(Object listener) throws TRADEException;
  }

  /** A listener-form request made here, while it lives; {@code id} is null while it is being made. */
  private static final class Mine {
    final Object listener;
    final Kind kind;
    final Object argument;
    String id; // Guarded by the client's lock.

    Mine(Object listener, Kind kind, Object argument) {
      this.listener = listener;
      this.kind = kind;
      this.argument = argument;
    }
  }

  private final Registry registry;
  private final ServiceCaller caller;
  private final InfoBinding infos;
  private final Registrar registrar;
  private final Function<Object, Query> queries;
  private final String requester;
  private final Object lock = new Object();
  // Guarded by lock.
  private final List<Mine> mine = new ArrayList<>();
  private final Set<Object> registeredHere = Collections.newSetFromMap(new IdentityHashMap<>());
  /** Ids told ended while requests were being made: one of them may be a request not yet in mine. */
  private final Set<String> endedEarly = new HashSet<>();
  /** "<container id>:" of containers whose notification service left, until forgetGone(). */
  private final Set<String> goneEngines = ConcurrentHashMap.newKeySet();

  /**
   * @param queries turns a {@code TRADEServiceConstraints} into a query (null for anything else):
   *     cancelling compares constraints by what they match
   */
  public NotificationClient(Registry registry, ServiceCaller caller, InfoBinding infos,
      Registrar registrar, Function<Object, Query> queries, String requester) {
    this.registry = registry;
    this.caller = caller;
    this.infos = infos;
    this.registrar = registrar;
    this.queries = queries;
    this.requester = requester;
    registry.addListener(this);
  }

  /**
   * Requests a notification whose callback is any service; see docs/notifications.md.
   *
   * @return its id, for {@link #cancel(String)} from any container
   */
  public String request(String type, Object argument, List<TRADEServiceInfo> services,
      TRADEServiceInfo callback) throws TRADEException {
    Objects.requireNonNull(callback, "callback == null");
    String where = services == null || services.isEmpty() ? registry.containerId()
        : infos.describe(services.get(0)).containerId();
    return callSystem(where, "requestNotification", String.class, type, argument,
        services == null ? List.of() : new ArrayList<>(services), callback, requester);
  }

  /** The TRADE 1.1.1 form: the callback is {@code listener}'s service {@code callbackMethod}. */
  public void request(Object listener, String type, Object argument, List<TRADEServiceInfo> services,
      String callbackMethod) throws TRADEException {
    Kind kind = Kind.parse(type);
    ServiceDescriptor service = services == null || services.isEmpty() ? null
        : infos.describe(services.get(0));
    Mine m = reserve(listener, kind, argument, false);
    String id = null;
    try {
      ServiceDescriptor cb = callbackOf(listener, callbackMethod, kind, service);
      id = request(type, argument, services, (TRADEServiceInfo) infos.bind(cb));
    } finally {
      made(m, id);
    }
  }
  /**
   * Calls back now for every service matching, then for each that joins.
   *
   * @return the services matching now, in preference order
   */
  public List<TRADEServiceInfo> requestNowOrWhenJoined(Object listener, Object constraints,
      String callbackMethod) throws TRADEException {
    Mine m = reserve(listener, Kind.JOINED, constraints, listener instanceof Waiter);
    String id = null;
    try {
      ServiceDescriptor cb = callbackOf(listener, callbackMethod, Kind.JOINED, null);
      Map<?, ?> r = callSystem(registry.containerId(), "requestNotificationNowOrWhenJoined", Map.class,
          constraints, infos.bind(cb), requester);
      List<TRADEServiceInfo> matches = new ArrayList<>();
      for (Object o : (List<?>) r.get("matches")) {
        matches.add((TRADEServiceInfo) o);
      }
      id = (String) r.get("id");
      return matches;
    } finally {
      made(m, id);
    }
  }

  /**
   * Cancels the listener's notifications of {@code type} requested here whose argument equals
   * {@code argument}, or all of that type when {@code argument} is null.
   *
   * @return how many were cancelled
   */
  public int cancel(Object listener, String type, Object argument) throws TRADEException {
    Kind kind = Kind.parse(type);
    forgetGone();
    List<String> ids = new ArrayList<>();
    synchronized (lock) {
      for (Iterator<Mine> it = mine.iterator(); it.hasNext(); ) {
        Mine m = it.next();
        if (m.id != null && m.listener == listener && m.kind == kind
            && (argument == null || sameArgument(m.argument, argument))) {
          it.remove();
          ids.add(m.id);
        }
      }
    }
    for (String id : ids) {
      cancel(id);
    }
    release(listener);
    return ids.size();
  }

  /**
   * The notification {@code id} ended (its container says so, whatever the reason): it is
   * forgotten here, and its listener released if this client registered it and nothing else of
   * it lives. Unknown ids (a notification requested elsewhere) are ignored.
   */
  public void ended(String id) throws TRADEException {
    forgetGone();
    Object listener = null;
    synchronized (lock) {
      for (Iterator<Mine> it = mine.iterator(); it.hasNext(); ) {
        Mine m = it.next();
        if (id.equals(m.id)) {
          it.remove();
          listener = m.listener;
          break;
        }
      }
      if (listener == null && hasPending()) {
        endedEarly.add(id);
      }
    }
    if (listener != null) {
      release(listener);
    }
  }

  /**
   * Notes the containers whose notification service left: the requests that ran there ended (or
   * died with them). Called under the registry's lock, so it only records them; the next request,
   * cancel or end here forgets those requests and releases their listeners.
   */
  @Override
  public void changed(List<Entry> added, List<Entry> removed) {
    for (Entry e : removed) {
      ServiceDescriptor d = e.descriptor();
      if (d.name().equals("cancelNotification") && d.groups().contains(SystemGroup.NAME)) {
        goneEngines.add(d.containerId() + ":");
      }
    }
  }

  /** Forgets the requests that ran in containers that left, and releases their listeners. */
  private void forgetGone() throws TRADEException {
    if (goneEngines.isEmpty()) {
      return;
    }
    Set<Object> listeners = Collections.newSetFromMap(new IdentityHashMap<>());
    synchronized (lock) {
      for (String prefix : List.copyOf(goneEngines)) {
        goneEngines.remove(prefix);
        for (Iterator<Mine> it = mine.iterator(); it.hasNext(); ) {
          Mine m = it.next();
          if (m.id != null && m.id.startsWith(prefix)) {
            it.remove();
            listeners.add(m.listener);
          }
        }
      }
    }
    for (Object l : listeners) {
      release(l);
    }
  }

  /** How many listener-form requests this client remembers (for tests). */
  int remembered() {
    synchronized (lock) {
      return mine.size();
    }
  }

  /**
   * Cancels the notification {@code id}, wherever it runs.
   *
   * @return whether it was live
   * @throws TRADEBadArgumentsException if {@code id} is not a notification id
   * @throws TRADEServiceUnavailableException if its container is not known here (any more)
   */
  public boolean cancel(String id) throws TRADEException {
    int at = id == null ? -1 : id.lastIndexOf(':');
    if (at <= 0) {
      throw new TRADEBadArgumentsException("Not a notification id: '" + id + "' (ids look like"
          + " <container id>:<number>)");
    }
    return callSystem(id.substring(0, at), "cancelNotification", Boolean.class, id);
  }

  /**
   * The preferred service matching {@code constraints}, now or as soon as one joins: a joined
   * notification, no polling.
   *
   * @throws TRADETimeoutException if none matched within {@code timeout}
   */
  public TRADEServiceInfo waitFor(Object constraints, Duration timeout) throws TRADEException {
    Waiter w = new Waiter();
    List<TRADEServiceInfo> now = requestNowOrWhenJoined(w, constraints, "joined");
    try {
      if (!now.isEmpty()) {
        return now.get(0);
      }
      return w.first.get(Math.max(0, timeout.toNanos()), TimeUnit.NANOSECONDS);
    } catch (TimeoutException e) {
      throw new TRADETimeoutException("No service matching " + constraints + " within "
          + timeout.toMillis() + " ms");
    } catch (ExecutionException e) {
      throw new IllegalStateException(e.getCause());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new TRADEException("Interrupted while waiting for a service matching " + constraints);
    } finally {
      cancel(w, "joined", null);
    }
  }

  /**
   * The listener of {@link #waitFor}: a service, as every callback, in the reserved group, open to
   * the notification engine's calls (which prove no principal).
   */
  @TRADEAccess(TRADEAccess.ANYONE)
  public static final class Waiter {
    final CompletableFuture<TRADEServiceInfo> first = new CompletableFuture<>();

    @TRADEService
    public void joined(TRADEServiceInfo info) {
      first.complete(info);
    }
  }

  private boolean sameArgument(Object a, Object b) {
    Query qa = a == null ? null : queries.apply(a);
    Query qb = queries.apply(b);
    return qa != null && qb != null ? qa.equals(qb)
        : Arrays.deepEquals(new Object[] {a}, new Object[] {b});
  }

  /** Calls system service {@code name} of container {@code containerId}. */
  private <T> T callSystem(String containerId, String name, Class<T> returnType, Object... args)
      throws TRADEException {
    return SystemServices.call(registry, caller, containerId, name, returnType, args);
  }

  /**
   * Registers {@code listener} if it is not, and remembers a request being made for it (id still
   * null), so that no end of another of its requests releases it meanwhile.
   */
  private Mine reserve(Object listener, Kind kind, Object argument, boolean system)
      throws TRADEException {
    Objects.requireNonNull(listener, "listener == null");
    forgetGone();
    synchronized (lock) {
      if (registry.servicesOf(listener) == null) {
        if (system) {
          registrar.registerSystem(listener);
        } else {
          registrar.register(listener);
        }
        registeredHere.add(listener);
      }
      Mine m = new Mine(listener, kind, argument);
      mine.add(m);
      return m;
    }
  }

  /**
   * The request {@code m} was made with result {@code id} (null: refused): keeps it unless it
   * ended already, else forgets it and releases its listener if nothing else of it lives.
   */
  private void made(Mine m, String id) throws TRADEException {
    boolean forget;
    synchronized (lock) {
      forget = id == null || endedEarly.remove(id);
      if (forget) {
        mine.remove(m);
      } else {
        m.id = id;
      }
      if (!hasPending()) {
        endedEarly.clear();
      }
    }
    if (forget) {
      release(m.listener);
    }
  }

  /** Whether a request is being made (guarded by lock). */
  private boolean hasPending() {
    for (Mine m : mine) {
      if (m.id == null) {
        return true;
      }
    }
    return false;
  }

  /** Deregisters {@code listener} if this client registered it and no request of it lives here. */
  private void release(Object listener) throws TRADEException {
    synchronized (lock) {
      for (Mine m : mine) {
        if (m.listener == listener) {
          return;
        }
      }
      if (registeredHere.remove(listener) && registry.servicesOf(listener) != null) {
        registrar.deregister(listener);
      }
    }
  }

  /** The listener's registered service {@code name} that can take what {@code kind} delivers. */
  private ServiceDescriptor callbackOf(Object listener, String name, Kind kind,
      ServiceDescriptor service) throws TRADEBadArgumentsException {
    if (name == null) {
      throw new TRADEBadArgumentsException("A notification needs a callback method name");
    }
    List<LocalService> services = registry.servicesOf(listener);
    TRADEBadArgumentsException first = null;
    for (LocalService s : services == null ? List.<LocalService>of() : services) {
      if (s.descriptor().name().equals(name)) {
        try {
          Shape.of(kind, service, s.descriptor());
          return s.descriptor();
        } catch (TRADEBadArgumentsException e) {
          first = first == null ? e : first;
        }
      }
    }
    if (first != null) {
      throw first;
    }
    boolean exists = false;
    for (Method m : listener.getClass().getMethods()) {
      exists |= m.getName().equals(name);
    }
    throw new TRADEBadArgumentsException("Callback " + listener.getClass().getName() + "." + name
        + " not usable: " + (exists ? "it must carry @" + TRADEService.class.getSimpleName()
            + " (callbacks are services)" : "there is no public method of that name"));
  }
}
