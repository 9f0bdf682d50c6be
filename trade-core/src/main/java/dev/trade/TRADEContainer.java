package dev.trade;

import dev.trade.internal.admin.AdminClient;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.config.LoggingConfig;
import dev.trade.internal.config.Settings;
import dev.trade.internal.container.ContainerCore;
import dev.trade.internal.hooks.Kind;
import dev.trade.internal.proxy.Proxies;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Suggestions;
import java.io.IOException;
import java.io.InputStream;
import dev.trade.internal.registry.Types;
import java.lang.annotation.Annotation;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Properties;
import java.util.Set;
import java.util.UUID;

/**
 * A TRADE container: it holds registered services, knows the services of every container of its
 * system, finds them by constraints and calls them.
 *
 * <p>Most programs use the JVM's default container through the static {@link TRADE} facade. Build
 * containers explicitly to run several in one JVM (tests, bridges):
 *
 * <pre>{@code
 * try (TRADEContainer c = TRADEContainer.builder().name("arm").build()) {
 *   c.registerAllServices(new RobotArm(), "MyRobot");
 *   c.getAvailableService(new TRADEServiceConstraints().name("openGripper")).call(void.class, 3);
 * }
 * }</pre>
 *
 * <p>Settings are fixed when the container is built. This class is safe for concurrent use.
 */
public final class TRADEContainer implements AutoCloseable {
  private final ContainerCore core;
  private final Proxies proxies;

  private TRADEContainer(Settings settings) {
    this.core = new ContainerCore(settings, new InfoBinding() {
      @Override
      public ServiceDescriptor describe(Object value) {
        return value instanceof TRADEServiceInfo ? ((TRADEServiceInfo) value).descriptor() : null;
      }

      @Override
      public Object bind(ServiceDescriptor descriptor) {
        return TRADEContainer.this.bind(descriptor);
      }
    }, argument -> argument == null ? new TRADEServiceConstraints().toQuery()
        : argument instanceof TRADEServiceConstraints ? ((TRADEServiceConstraints) argument).toQuery()
        : null);
    this.proxies = new Proxies(new Proxies.Services() {
      @Override
      public TRADEServiceInfo find(TRADEServiceConstraints constraints, String name,
          Class<?>[] parameterTypes) throws TRADEException {
        TRADEServiceConstraints base = constraints == null ? new TRADEServiceConstraints() : constraints;
        return getAvailableService(base.narrowed(name, parameterTypes));
      }

      @Override
      public Object generation() {
        return core.registry().generation();
      }
    }, core.name());
  }

  /**
   * A builder starting from the built-in defaults (no configuration file is read).
   *
   * @return a new builder
   */
  public static Builder builder() {
    return new Builder();
  }

  /**
   * This container's name.
   *
   * @return the {@code CONTAINERNAME} setting, or a name derived from host and pid
   */
  public String getName() {
    return core.name();
  }

  /**
   * The id of this container's incarnation.
   *
   * @return an id that is unique, new at every start
   */
  public String getId() {
    return core.containerId();
  }

  /**
   * The host name this container reports for its services.
   *
   * @return the host name
   */
  public String getHost() {
    return core.host();
  }

  /**
   * Registers every {@link TRADEService} method of {@code provider} as a service in
   * {@code groups}; null, empty or blank group names mean no group. All or nothing.
   *
   * <pre>{@code
   * Collection<TRADEServiceInfo> mine = container.registerAllServices(new RobotArm(), List.of("MyRobot"));
   * }</pre>
   *
   * <p>An object without service methods registers nothing, and a WARNING names its class and
   * the rule (a service is a public method annotated {@code @TRADEService}, on the class or on an
   * interface it implements).
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADERegistrationException if {@code provider} is already registered, or one of its
   *     annotated methods cannot be a service (the message names the method and the fix)
   */
  public Collection<TRADEServiceInfo> registerAllServices(Object provider, Collection<String> groups)
      throws TRADEException {
    Objects.requireNonNull(provider, "provider == null");
    checkOpen();
    List<LocalService> services = core.register(provider, normalize(groups));
    List<TRADEServiceInfo> infos = new ArrayList<>(services.size());
    for (LocalService s : services) {
      infos.add(bind(s.descriptor()));
    }
    return infos;
  }

  /**
   * As {@link #registerAllServices(Object, Collection)}; {@code (String) null} means no group.
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link #registerAllServices(Object, Collection)}
   */
  public Collection<TRADEServiceInfo> registerAllServices(Object provider, String... groups)
      throws TRADEException {
    return registerAllServices(provider, groups == null ? List.of() : Arrays.asList(groups));
  }

  /**
   * The TRADE paper's name for {@link #registerAllServices(Object, String...)} with one group.
   *
   * @param provider the object whose methods become services; not null
   * @param group the group of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link #registerAllServices(Object, Collection)}
   */
  public Collection<TRADEServiceInfo> register(Object provider, String group) throws TRADEException {
    return registerAllServices(provider, group);
  }

  /**
   * The TRADE paper's name for {@link #registerAllServices(Object, Collection)}.
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link #registerAllServices(Object, Collection)}
   */
  public Collection<TRADEServiceInfo> register(Object provider, Collection<String> groups)
      throws TRADEException {
    return registerAllServices(provider, groups);
  }

  /**
   * Removes every service of {@code provider}. Calls already running finish; later calls through
   * existing infos fail with {@link TRADEServiceUnavailableException}.
   *
   * @param provider an object registered here
   * @throws TRADEServiceNotFoundException if {@code provider} is not registered here
   */
  public void deregister(Object provider) throws TRADEException {
    Objects.requireNonNull(provider, "provider == null");
    core.deregister(provider);
  }

  /**
   * The preferred service matching {@code constraints}: one of this container first (the earliest
   * registered), then the nearest container's, then by container id and registration order.
   *
   * <pre>{@code
   * TRADEServiceInfo open = container.getAvailableService(
   *     new TRADEServiceConstraints().name("openGripper").argTypes(int.class));
   * }</pre>
   *
   * @return the preferred matching service
   * @param constraints null matches every service
   * @throws TRADEServiceNotFoundException if none matches; the message names the constraints and,
   *     when they name a service, the known services of that name or of the nearest names, with
   *     their signatures
   */
  public TRADEServiceInfo getAvailableService(TRADEServiceConstraints constraints)
      throws TRADEException {
    checkOpen();
    TRADEServiceConstraints c = constraints == null ? new TRADEServiceConstraints() : constraints;
    Entry e = core.registry().findFirst(c.requiredName(), c.toQuery());
    if (e == null) {
      throw new TRADEServiceNotFoundException("No service matches " + c
          + Suggestions.hint(core.registry().all(), c.requiredName()));
    }
    return bind(e.descriptor());
  }

  /**
   * Every service of the system.
   *
   * @return the services, in preference order; maybe none
   */
  public Collection<TRADEServiceInfo> getAvailableServices() {
    return getAvailableServices(null);
  }

  /**
   * Every service matching {@code constraints}.
   *
   * @param constraints the constraints; null matches every service
   * @return the matches, in preference order; maybe none
   */
  public Collection<TRADEServiceInfo> getAvailableServices(TRADEServiceConstraints constraints) {
    checkOpen();
    TRADEServiceConstraints c = constraints == null ? new TRADEServiceConstraints() : constraints;
    return bindAll(core.registry().find(c.requiredName(), c.toQuery()), null);
  }

  /**
   * Every service matching {@code constraints} (null: all) whose method, or a declaration it
   * overrides, carries {@code annotation}, in preference order; maybe none. Services of other
   * containers are included when this JVM knows the annotation's class (which it does, since the
   * caller names it): their annotations travel with their descriptions.
   *
   * @param annotation an annotation type, such as DIARC's {@code Action.class}
   * @param constraints the constraints; null matches every service
   * @return the matches, in preference order; maybe none
   * @throws IllegalArgumentException if {@code annotation} is not an annotation type
   */
  public Collection<TRADEServiceInfo> getAvailableServices(
      Class<?> annotation, TRADEServiceConstraints constraints) {
    Objects.requireNonNull(annotation, "annotation == null");
    if (!annotation.isAnnotation()) {
      throw new IllegalArgumentException("getAvailableServices(annotation, constraints): "
          + annotation.getName() + " is not an annotation type; pass the class of an annotation,"
          + " such as TRADEService.class");
    }
    checkOpen();
    TRADEServiceConstraints c = constraints == null ? new TRADEServiceConstraints() : constraints;
    return bindAll(core.registry().find(c.requiredName(), c.toQuery()), annotation);
  }

  /**
   * The addresses this container accepts connections on ({@code SERVERIPS}; with port 0 the port
   * actually chosen).
   *
   * @return the addresses as {@code ip@port}; empty when it does not accept connections
   */
  public List<String> getServerAddresses() {
    List<String> result = new ArrayList<>();
    for (InetSocketAddress a : core.listenAddresses()) {
      String ip = a.getAddress().getHostAddress();
      result.add((ip.contains(":") ? "[" + ip + "]" : ip) + "@" + a.getPort());
    }
    return result;
  }

  /**
   * Requests a notification whose callback is {@code listener}'s {@code @TRADEService} method
   * {@code callbackMethod} (TRADE 1.1.1's form). Types and arguments (docs/notifications.md):
   * {@code "joined"}/{@code "left"} (argument: {@code TRADEServiceConstraints} or null for all;
   * the callback takes the {@code TRADEServiceInfo} that joined or left, anywhere in the system),
   * {@code "once"} (calls {@code services[0]} with the argument's values, without blocking, and
   * hands its result to the callback), {@code "after"} (a delay: {@code long} ms or
   * {@code Duration}), {@code "at"} (an {@code Instant}), {@code "every"} (a period; with a
   * service, its result each period), {@code "if"} (a time; calls back only if the condition
   * {@code services[0]} is true then) and {@code "when"} (a period; calls back once, the first time
   * the condition is true).
   *
   * <p>The notification runs in the container providing {@code services[0]}, else in this one;
   * every callback, condition and service is called as a service. A listener that is not
   * registered yet is registered now, in no group; this container deregisters it again when
   * {@link #cancelNotification(Object, String, Object)} cancels its last notification requested
   * here (or call {@link #deregister}, which ends its notifications). Joined and left events reach
   * the callback one at a time, in the order the changes happened; a callback that throws is logged
   * and counted and does not end the notification.
   *
   * @param listener the object with the callback method; not null
   * @param type a notification type: joined, left, once, after, at, every, if or when
   * @param argument what the type takes (constraints, a delay, an instant, a period, with a
   *     service's arguments after it), or null
   * @param services the service called or the condition, as {@code services[0]}; null or empty
   *     for types that take none
   * @param callbackMethod the name of the listener's callback method
   * @throws TRADEBadArgumentsException a bad request: an unknown type (the message lists the
   *     supported ones), an argument of the wrong kind, a period below 1 ms, a missing service or
   *     one that is not a condition, or no callback method that can take what the type delivers
   *     (the message names the method and the parameter types expected); nothing is scheduled
   * @throws TRADEServiceUnavailableException {@code services[0]}'s container is not reachable
   */
  public void requestNotification(Object listener, String type, Object argument,
      List<TRADEServiceInfo> services, String callbackMethod) throws TRADEException {
    checkOpen();
    core.notifications().request(listener, type, argument, services, callbackMethod);
  }

  /**
   * Requests a notification whose callback is any service, of any container: see
   * {@link #requestNotification(Object, String, Object, List, String)} for types and arguments.
   *
   * @param type a notification type
   * @param argument what the type takes, or null
   * @param services the service called or the condition, as {@code services[0]}; or null
   * @param callback the service called back
   * @return the notification's id, which {@link #cancelNotification(String)} cancels from any
   *     container
   * @throws TRADEException as {@link #requestNotification(Object, String, Object, List, String)}
   */
  public String requestNotification(String type, Object argument, List<TRADEServiceInfo> services,
      TRADEServiceInfo callback) throws TRADEException {
    checkOpen();
    return core.notifications().request(type, argument, services, callback);
  }

  /**
   * Cancels the listener's notifications of {@code type} requested through this container whose
   * argument equals {@code argument}, or all of that type when {@code argument} is null. Events
   * already queued for a cancelled notification are not delivered.
   *
   * @param listener the listener of the requests
   * @param type their type
   * @param argument their argument; null for all of that type
   * @throws TRADEException {@link TRADEBadArgumentsException} for an unknown type
   */
  public void cancelNotification(Object listener, String type, Object argument)
      throws TRADEException {
    core.notifications().cancel(listener, type, argument);
  }

  /**
   * Cancels the notification {@code id}, wherever it runs.
   *
   * @param id what {@link #requestNotification(String, Object, List, TRADEServiceInfo)} returned
   * @return whether it was live (false: it ended already, or was never known)
   * @throws TRADEBadArgumentsException {@code id} is not a notification id
   * @throws TRADEServiceUnavailableException the container that runs it is not known here
   * @throws TRADEException another failure of the cancelling call
   */
  public boolean cancelNotification(String id) throws TRADEException {
    checkOpen();
    return core.notifications().cancel(id);
  }

  /**
   * Calls {@code listener.callbackMethod(TRADEServiceInfo)} now for every service already matching
   * {@code constraints}, and then for every one that joins: without a race between the two, so
   * each service is delivered exactly once. Cancel it as a {@code "joined"} notification.
   *
   * @param listener the object with the callback method; not null
   * @param constraints the services of interest (null: all)
   * @param callbackMethod the name of the callback method
   * @return the services matching now, in preference order (those called back at once)
   * @throws TRADEException as {@link #requestNotification(Object, String, Object, List, String)}
   */
  public Collection<TRADEServiceInfo> registerNotificationNowOrWhenJoined(Object listener,
      TRADEServiceConstraints constraints, String callbackMethod) throws TRADEException {
    checkOpen();
    return core.notifications().requestNowOrWhenJoined(listener, constraints, callbackMethod);
  }

  /**
   * The preferred service matching {@code constraints} now, or the first that joins within
   * {@code timeout}: built on a joined notification, without polling.
   *
   * @param constraints null matches every service
   * @param timeout the longest to wait
   * @return the service
   * @throws TRADETimeoutException if none matched within {@code timeout}
   * @throws TRADEException if the container is closed meanwhile
   */
  public TRADEServiceInfo waitForService(TRADEServiceConstraints constraints, Duration timeout)
      throws TRADEException {
    Objects.requireNonNull(timeout, "timeout == null");
    checkOpen();
    return core.notifications().waitFor(constraints, timeout);
  }

  /**
   * Locks every service (of any container) registered in all of {@code groups}, all or none, at
   * once or not at all: TRADE 1.1.1's form. Use the id with
   * {@link TRADEServiceInfo#call(UUID, Class, Object...)} and {@link #releaseLock(UUID)}.
   *
   * @param groups the groups every service to lock is in; not empty
   * @return the lock's id, or null when any of those services is held by another lock (or awaited
   *     by an earlier request)
   * @throws UncheckedTRADEException wrapping {@link TRADEBadArgumentsException} when
   *     {@code groups} is empty or no service matches, or another {@link TRADEException} when a
   *     container cannot be reached; nothing is locked then
   */
  public UUID lockServicesContainAll(Collection<String> groups) {
    TRADEServiceConstraints c = new TRADEServiceConstraints().inGroups(groupArray(groups));
    return lockAtOnce(getAvailableServices(c), groups);
  }

  /**
   * Locks every service (of any container) registered in at least one of {@code groups}, all or
   * none, at once or not at all: TRADE 1.1.1's form; see {@link #lockServicesContainAll}.
   *
   * @param groups the groups; a service in any of them is locked; not empty
   * @return the lock's id, or null when any of those services is held by another lock (or awaited
   *     by an earlier request)
   * @throws UncheckedTRADEException as {@link #lockServicesContainAll}
   */
  public UUID lockServicesContainOne(Collection<String> groups) {
    Set<TRADEServiceInfo> services = new LinkedHashSet<>();
    for (String g : groupArray(groups)) {
      services.addAll(getAvailableServices(new TRADEServiceConstraints().inGroups(g)));
    }
    return lockAtOnce(services, groups);
  }

  private UUID lockAtOnce(Collection<TRADEServiceInfo> services, Collection<String> groups) {
    try {
      if (services.isEmpty()) {
        throw new TRADEBadArgumentsException("No service is in the groups " + groups
            + "; nothing to lock");
      }
      return lock(services, Duration.ZERO).getId();
    } catch (TRADELockedException e) {
      return null;
    } catch (TRADEException e) {
      throw new UncheckedTRADEException(e);
    }
  }

  private static String[] groupArray(Collection<String> groups) {
    Set<String> g = normalize(groups);
    if (g.isEmpty()) {
      throw new UncheckedTRADEException(new TRADEBadArgumentsException("A lock needs at least one"
          + " group: groups is " + (groups == null ? "null" : "empty")));
    }
    return g.toArray(new String[0]);
  }

  /**
   * Locks {@code services}, wherever they are, all or none: waits up to {@code maxWait} for them to
   * be free, first come first served per service. The lock is owned by this container: calls under
   * it are made from here, and it lasts while this container lives and reaches the services'
   * containers (docs/locks.md).
   *
   * <pre>{@code
   * try (TRADELock lock = container.lock(List.of(head), Duration.ofSeconds(5))) {
   *   head.call(lock.getId(), void.class, 30.0);
   * }
   * }</pre>
   *
   * @param services the services to lock; not empty
   * @param maxWait the longest to wait for them; zero to take them only if free now
   * @return the lock
   * @throws TRADELockedException if one is still held by another lock when {@code maxWait} ends
   *     (the message names that lock, its container and since when)
   * @throws TRADEBadArgumentsException if {@code services} is empty or names a system service
   * @throws TRADEServiceUnavailableException if one is not available (any more)
   * @throws TRADEException if a container cannot be reached; nothing is locked then
   */
  public TRADELock lock(Collection<TRADEServiceInfo> services, Duration maxWait)
      throws TRADEException {
    Objects.requireNonNull(maxWait, "maxWait == null");
    checkOpen();
    List<ServiceDescriptor> ds = new ArrayList<>();
    for (TRADEServiceInfo s : services == null ? List.<TRADEServiceInfo>of() : services) {
      ds.add(Objects.requireNonNull(s, "services contains null").descriptor());
    }
    long wait = maxWait.isNegative() ? 0 : maxWait.compareTo(Duration.ofDays(1)) > 0
        ? Duration.ofDays(1).toNanos() : maxWait.toNanos();
    return new TRADELock(this, core.locks().client(), core.locks().client().acquire(ds, wait));
  }

  /**
   * Locks every service matching {@code constraints}; see {@link #lock(Collection, Duration)}.
   *
   * @param constraints the services to lock; null matches every service
   * @param maxWait the longest to wait for them; zero to take them only if free now
   * @return the lock
   * @throws TRADEException as {@link #lock(Collection, Duration)}; {@link TRADEBadArgumentsException}
   *     when nothing matches
   */
  public TRADELock lock(TRADEServiceConstraints constraints, Duration maxWait)
      throws TRADEException {
    return lock(getAvailableServices(constraints), maxWait);
  }

  /**
   * Releases lock {@code lock}: in every container where it holds services, they are free again.
   *
   * @param lock the lock's id
   * @throws TRADEException {@link TRADEBadArgumentsException} if no lock of that id is held
   *     (released already, its lease ended, or never granted);
   *     {@link TRADENotAuthorizedException} if another container owns it
   */
  public void releaseLock(UUID lock) throws TRADEException {
    checkOpen();
    core.locks().client().release(lock);
  }

  /**
   * Every lock's claims on services, from every container that answers: for each locked service
   * its holder, then the locks waiting for it in the order they will be served.
   *
   * @return the claims, by container, then by service; maybe none
   * @throws TRADEException if this container is closed meanwhile
   */
  public List<TRADELockInfo> getLocks() throws TRADEException {
    checkOpen();
    List<TRADELockInfo> infos = new ArrayList<>();
    for (Map<String, Object> m : core.locks().client().list()) {
      Object service = m.get("service");
      if (service instanceof TRADEServiceInfo) {
        infos.add(new TRADELockInfo((TRADEServiceInfo) service,
            UUID.fromString((String) m.get("lock")), (String) m.get("container"),
            (String) m.get("containerName"), (String) m.get("principal"),
            (Instant) m.get("since"), (Boolean) m.get("holding"),
            ((Number) m.get("token")).longValue()));
      }
    }
    return infos;
  }

  /**
   * Calls {@code wrapper} before every call of {@code target}, wherever the call comes from (TRADE
   * 1.1.1's {@code beforeService}): the hook is installed in the container that provides
   * {@code target}, so it sees local, remote, forwarded and notification calls and calls made by
   * other hooks. The wrapper is a service taking one {@code Object[]}: {@code [serviceName, arg1,
   * ..., argN]}, an array of its own; it cannot change the arguments {@code target} receives (the
   * argument objects themselves are shared within a container unless strict mode,
   * {@code COPYDATAFORLOCALINVOKES}, is on: do not mutate them). The target waits for it, at most
   * {@code HOOKTIMEOUT}; a wrapper that fails is logged and counted and never fails the call.
   * Several hooks on one target run in the order they were added; adding the same hook again
   * changes nothing. See docs/hooks.md.
   *
   * @param wrapper the service called before the target; it takes one {@code Object[]}
   * @param target the service instrumented, of any container
   * @throws TRADEBadArgumentsException the wrapper does not take one {@code Object[]}, or the target
   *     is a system service its container does not let hooks wrap ({@code HOOKSYSTEMSERVICES})
   * @throws TRADEServiceUnavailableException the target's container cannot be reached, or the
   *     target or wrapper is gone
   * @throws TRADEException another failure of the call that installs the hook
   */
  public void beforeService(TRADEServiceInfo wrapper, TRADEServiceInfo target) throws TRADEException {
    checkOpen();
    core.hooks().add(Kind.BEFORE, wrapper, target);
  }

  /**
   * Calls {@code wrapper} after every call of {@code target} and before its caller gets the result
   * (TRADE 1.1.1's {@code afterService}); as {@link #beforeService(TRADEServiceInfo,
   * TRADEServiceInfo)} otherwise. The wrapper's array is {@code [serviceName, arg1, ..., argN,
   * result]}, the result {@code null} for a {@code void} target and for a call that threw; a
   * wrapper taking {@code (Object[], Throwable)} also receives the failure the caller receives
   * ({@code null} when the target returned), which is how a hook learns that the target threw.
   *
   * @param wrapper the service called after the target; it takes one {@code Object[]}, or an
   *     {@code Object[]} and a {@code Throwable}
   * @param target the service instrumented, of any container
   * @throws TRADEException as {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public void afterService(TRADEServiceInfo wrapper, TRADEServiceInfo target) throws TRADEException {
    afterService(wrapper, target, false);
  }

  /**
   * As {@link #afterService(TRADEServiceInfo, TRADEServiceInfo)}; an asynchronous hook is called on
   * the target container's hook pool after the call returned, so the caller never waits for it.
   *
   * @param wrapper the service called after the target
   * @param target the service instrumented, of any container
   * @param asynchronous whether the caller's result does not wait for the wrapper
   * @throws TRADEException as {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public void afterService(TRADEServiceInfo wrapper, TRADEServiceInfo target, boolean asynchronous)
      throws TRADEException {
    checkOpen();
    core.hooks().add(asynchronous ? Kind.AFTER_ASYNC : Kind.AFTER, wrapper, target);
  }

  /**
   * The TRADE paper's form of {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}: wrapper
   * and target are the preferred services matching a name, parameter types and constraints.
   *
   * @param wrapperName the wrapper's name
   * @param wrapperArgTypeNames the wrapper's parameter type names ({@code Object[].class.getName()}
   *     or {@code java.lang.Object[]}); null: any
   * @param wrapperConstraints what the wrapper must also match; null: nothing more
   * @param targetName the target's name
   * @param targetArgTypeNames the target's parameter type names; null: any
   * @param targetConstraints what the target must also match; null: nothing more
   * @throws TRADEServiceNotFoundException no service matches the wrapper's or the target's
   *     description
   * @throws TRADEBadArgumentsException a parameter type name names no class known here
   * @throws TRADEException as {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public void beforeService(String wrapperName, String[] wrapperArgTypeNames,
      TRADEServiceConstraints wrapperConstraints, String targetName, String[] targetArgTypeNames,
      TRADEServiceConstraints targetConstraints) throws TRADEException {
    beforeService(find(wrapperName, wrapperArgTypeNames, wrapperConstraints),
        find(targetName, targetArgTypeNames, targetConstraints));
  }

  /**
   * The TRADE paper's form of {@link #afterService(TRADEServiceInfo, TRADEServiceInfo)}:
   * {@code afterService("addObservedOutput", new String[] {Object[].class.getName()}, null,
   * serviceName, serviceArgs, constraints)}.
   *
   * @param wrapperName the wrapper's name
   * @param wrapperArgTypeNames the wrapper's parameter type names; null: any
   * @param wrapperConstraints what the wrapper must also match; null: nothing more
   * @param targetName the target's name
   * @param targetArgTypeNames the target's parameter type names; null: any
   * @param targetConstraints what the target must also match; null: nothing more
   * @throws TRADEException as {@link #beforeService(String, String[], TRADEServiceConstraints,
   *     String, String[], TRADEServiceConstraints)}
   */
  public void afterService(String wrapperName, String[] wrapperArgTypeNames,
      TRADEServiceConstraints wrapperConstraints, String targetName, String[] targetArgTypeNames,
      TRADEServiceConstraints targetConstraints) throws TRADEException {
    afterService(find(wrapperName, wrapperArgTypeNames, wrapperConstraints),
        find(targetName, targetArgTypeNames, targetConstraints));
  }

  /**
   * Removes the before hook of {@code wrapper} on {@code target} (TRADE 1.1.1 has no removal).
   *
   * @param wrapper the hook's wrapper
   * @param target the hook's target
   * @return whether there was such a hook
   * @throws TRADEServiceUnavailableException the target's container cannot be reached
   * @throws TRADEException another failure of the call that removes the hook
   */
  public boolean removeBeforeService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    checkOpen();
    return core.hooks().remove(Kind.BEFORE, wrapper, target);
  }

  /**
   * Removes the after hook, synchronous or asynchronous, of {@code wrapper} on {@code target}.
   *
   * @param wrapper the hook's wrapper
   * @param target the hook's target
   * @return whether there was such a hook
   * @throws TRADEException as {@link #removeBeforeService}
   */
  public boolean removeAfterService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    checkOpen();
    boolean sync = core.hooks().remove(Kind.AFTER, wrapper, target);
    return core.hooks().remove(Kind.AFTER_ASYNC, wrapper, target) || sync;
  }

  /**
   * Calls {@code wrapper} before every call of every service matching {@code targets}, now and as
   * services join, in any container, as DIARC's service tracker needs; the wrapper itself is never
   * one of its targets. System services match only constraints that name the group
   * {@code trade.system}, and only where their container allows it ({@code HOOKSYSTEMSERVICES}).
   * A service that joins is covered from when its hook reaches its container, one call after this
   * container learns of it; a target that refuses the hook or cannot be reached is logged and
   * left out. The set lives in this container: it stops covering new services when this container
   * closes, and its hooks end everywhere when its wrapper leaves.
   *
   * @param wrapper the service called before each target; it takes one {@code Object[]}
   * @param targets the services to instrument
   * @return how many services it covers now
   * @throws TRADEServiceUnavailableException the wrapper is not known here
   * @throws TRADEException another failure
   */
  public int beforeServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    checkOpen();
    return core.hooks().addSet(Kind.BEFORE, wrapper, targetsOf(targets));
  }

  /**
   * As {@link #beforeServices}, after the calls: see {@link #afterService(TRADEServiceInfo,
   * TRADEServiceInfo)}.
   *
   * @param wrapper the service called after each target
   * @param targets the services to instrument
   * @return how many services it covers now
   * @throws TRADEException as {@link #beforeServices}
   */
  public int afterServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    return afterServices(wrapper, targets, false);
  }

  /**
   * As {@link #afterServices(TRADEServiceInfo, TRADEServiceConstraints)}, asynchronous if asked:
   * see {@link #afterService(TRADEServiceInfo, TRADEServiceInfo, boolean)}.
   *
   * @param wrapper the service called after each target
   * @param targets the services to instrument
   * @param asynchronous whether callers' results do not wait for the wrapper
   * @return how many services it covers now
   * @throws TRADEException as {@link #beforeServices}
   */
  public int afterServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets,
      boolean asynchronous) throws TRADEException {
    checkOpen();
    return core.hooks().addSet(asynchronous ? Kind.AFTER_ASYNC : Kind.AFTER, wrapper,
        targetsOf(targets));
  }

  /**
   * Removes the set hook that {@link #beforeServices} added here with this wrapper and constraints
   * that match the same services, and its hooks in every container.
   *
   * @param wrapper the set's wrapper
   * @param targets the set's constraints
   * @return whether there was such a set
   * @throws TRADEException if the wrapper is not a service info
   */
  public boolean removeBeforeServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    checkOpen();
    return core.hooks().removeSet(Kind.BEFORE, wrapper, targetsOf(targets));
  }

  /**
   * Removes the set hook, synchronous or asynchronous, that {@link #afterServices} added here with
   * this wrapper and constraints that match the same services, and its hooks everywhere.
   *
   * @param wrapper the set's wrapper
   * @param targets the set's constraints
   * @return whether there was such a set
   * @throws TRADEException if the wrapper is not a service info
   */
  public boolean removeAfterServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    checkOpen();
    boolean sync = core.hooks().removeSet(Kind.AFTER, wrapper, targetsOf(targets));
    return core.hooks().removeSet(Kind.AFTER_ASYNC, wrapper, targetsOf(targets)) || sync;
  }

  /**
   * The hooks installed in every container known here, as their hook services list them: one
   * map each with {@code id}, {@code kind} ({@code before}, {@code after}, {@code after-async}),
   * {@code wrapper} and {@code target} ({@code signature@container}), {@code set} (the set hook's
   * id, or empty), {@code requester}, {@code calls} and {@code failures}. A container that cannot
   * be reached is left out.
   *
   * @return the hooks, each container's in order of addition
   */
  public List<Map<String, Object>> getHooks() {
    checkOpen();
    return core.callEverywhere("listHooks");
  }

  /**
   * Starts this container's call log: one JSON line per call of every service in any of
   * {@code groups} (none: every service but the system services), in every container, now and as
   * they join, written to {@code file} (rotated at {@code CALLLOGMAXBYTES} to {@code <file>.1}).
   * It is built on asynchronous after hooks, so callers never wait for it; it also switches this
   * container's call statistics on ({@link #getCallStatistics()}). The {@code CALLLOG} setting
   * starts it with the container. See docs/hooks.md for the lines.
   *
   * @param file the file to append to; its directory must exist
   * @param groups the groups whose services are logged; none: all
   * @return the file's absolute path
   * @throws TRADEBadArgumentsException a call log runs here already, or the file cannot be opened
   * @throws TRADEException another failure of the call to this container's call log service
   */
  public String startCallLog(String file, String... groups) throws TRADEException {
    Objects.requireNonNull(file, "file == null");
    checkOpen();
    return core.callSystem("startCallLog", String.class, file, new ArrayList<>(normalize(
        groups == null ? List.of() : Arrays.asList(groups))), 0);
  }

  /**
   * Stops this container's call log and removes its hooks everywhere.
   *
   * @return whether one ran
   * @throws TRADEException a failure of the call to this container's call log service
   */
  public boolean stopCallLog() throws TRADEException {
    checkOpen();
    return core.callSystem("stopCallLog", Boolean.class);
  }

  /**
   * Switches this container's call statistics on or off: while on, an observer of its host chain
   * counts each of its services' calls, failures and durations (two clock reads per call).
   *
   * @param on whether to count
   * @throws TRADEException a failure of the call to this container's call log service
   */
  public void setCallStatistics(boolean on) throws TRADEException {
    checkOpen();
    core.callSystem("setCallStatistics", void.class, on);
  }

  /**
   * The call statistics of every container known here whose statistics are or were on: one map
   * per service, with {@code service} (its signature), {@code container} (its name), {@code calls},
   * {@code failures} (longs), {@code p50Micros} and {@code p99Micros} (doubles, within 12.5 %:
   * the time the host chain spent on the call, hooks excluded). A container that cannot be
   * reached is left out.
   *
   * @return the statistics, each container's by signature
   */
  public List<Map<String, Object>> getCallStatistics() {
    checkOpen();
    return core.callEverywhere("callStatistics");
  }

  private static TRADEServiceConstraints targetsOf(TRADEServiceConstraints targets) {
    return targets == null ? new TRADEServiceConstraints() : targets.copy();
  }

  /** The preferred service named {@code name} with those parameter types and constraints. */
  private TRADEServiceInfo find(String name, String[] argTypeNames,
      TRADEServiceConstraints constraints) throws TRADEException {
    Objects.requireNonNull(name, "name == null");
    TRADEServiceConstraints c = constraints == null ? new TRADEServiceConstraints()
        : constraints.copy();
    c.name(name);
    if (argTypeNames != null) {
      Class<?>[] types = new Class<?>[argTypeNames.length];
      ClassLoader loader = Thread.currentThread().getContextClassLoader();
      for (int i = 0; i < types.length; i++) {
        types[i] = Types.resolve(Objects.requireNonNull(argTypeNames[i], "argTypeNames[" + i
            + "] == null"), loader != null ? loader : TRADEContainer.class.getClassLoader());
        if (types[i] == null) {
          throw new TRADEBadArgumentsException("Parameter type '" + argTypeNames[i] + "' of "
              + name + " names no class known here: give Class.getName() or getTypeName() of a"
              + " class on the class path");
        }
      }
      c.argTypes(types);
    }
    return getAvailableService(c);
  }

  /**
   * Switches multicast discovery on or off at run time: while on, this container listens for the
   * announcements of containers of its system ({@code TRADESYSID}, {@code CREDENTIALS}) and connects
   * to them. See docs/discovery.md.
   *
   * @param on whether to discover
   * @throws java.io.UncheckedIOException if discovery cannot open its socket
   */
  public void setDiscovery(boolean on) {
    checkOpen();
    core.setDiscovery(on);
  }

  /**
   * Switches announcing this container by multicast on or off at run time; while on, it accepts
   * connections (on {@code SERVERIPS}, or where the discovery range reaches).
   *
   * @param on whether to announce
   * @throws java.io.UncheckedIOException if a socket cannot be opened
   */
  public void setBroadcast(boolean on) {
    checkOpen();
    core.setBroadcast(on);
  }

  /**
   * Whether discovery is on.
   *
   * @return true while this container discovers others
   */
  public boolean isDiscovering() {
    return core.isDiscovering();
  }

  /**
   * Whether this container announces itself.
   *
   * @return true while it announces
   */
  public boolean isBroadcasting() {
    return core.isBroadcasting();
  }

  /**
   * The ids of the containers this one has a direct, authenticated link to right now: an
   * unmodifiable snapshot.
   *
   * @return the neighbours' container ids
   */
  public List<String> getNeighbours() {
    return core.neighbours();
  }

  // ---- The middleware's own operations (docs/middleware-services.md) ----

  /**
   * Switches multicast discovery of this container on or off, as {@code credentials}: through
   * this container's middleware service {@code setDiscovery}, which by default only a principal
   * with the role {@code admin} may call.
   *
   * @param credentials {@code <principal>:<secret>} of a principal in this container's access file
   *     ({@code PRINCIPALSFILE}); anything else is anonymous
   * @param on whether to discover
   * @throws TRADENotAuthorizedException if the principal may not (the message says what is
   *     missing)
   * @throws TRADEException if discovery cannot be switched (its cause says why)
   */
  public void setDiscovery(String credentials, boolean on) throws TRADEException {
    admin(credentials, "setDiscovery", void.class, on);
  }

  /**
   * Switches announcing this container on or off, as {@code credentials}; see
   * {@link #setDiscovery(String, boolean)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param on whether to announce
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if announcing cannot be switched
   */
  public void setBroadcast(String credentials, boolean on) throws TRADEException {
    admin(credentials, "setBroadcast", void.class, on);
  }

  /**
   * Asks for encryption on or off, as {@code credentials}. Encryption is chosen per link at its
   * handshake from {@code USEENCRYPTION} and cannot change while the container runs: asking for
   * the setting it has succeeds, the other fails.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param on whether links should be encrypted
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEBadArgumentsException if {@code on} differs from {@code USEENCRYPTION} (the
   *     message says to change the setting and restart)
   * @throws TRADEException if the call fails otherwise
   */
  public void setEncryption(String credentials, boolean on) throws TRADEException {
    admin(credentials, "setEncryption", void.class, on);
  }

  /**
   * Accepts connections on {@code ip} and {@code port} too, as {@code credentials}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param ip the address to listen on, such as {@code 127.0.0.1}
   * @param port the port; 0 for any free port ({@link #getServerAddresses()} tells which)
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the address cannot be bound (its cause says why)
   */
  public void startListenForConnections(String credentials, String ip, int port)
      throws TRADEException {
    admin(credentials, "startListenForConnections", String.class, ip, port);
  }

  /**
   * Stops accepting connections, as {@code credentials}; links already made stay.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the call fails otherwise
   */
  public void stopListenForConnections(String credentials) throws TRADEException {
    admin(credentials, "stopListenForConnections", List.class);
  }

  /**
   * Lets other containers call this container's ordinary services, or stops them, as
   * {@code credentials}. While off, calls from other containers to ordinary services are refused
   * with {@link TRADENotAuthorizedException}; system services stay under their policy, so an
   * administrator can switch it on again from elsewhere.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param allowed whether other containers may call this container's services
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the call fails otherwise
   */
  public void accessToTRADEServices(String credentials, boolean allowed) throws TRADEException {
    admin(credentials, "setRemoteAccess", void.class, allowed);
  }

  /**
   * Reads the network interfaces again, as {@code credentials}: while this container announces
   * itself, it announces the addresses of the interfaces up now at once.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the call fails otherwise
   */
  public void findInterfaces(String credentials) throws TRADEException {
    admin(credentials, "findInterfaces", List.class);
  }

  /**
   * The containers of the system and their links, as each says itself (its middleware service
   * {@code neighbours}, called as {@code credentials}).
   *
   * @param credentials {@code <principal>:<secret>} of a principal that every container's access
   *     file lets call its middleware services
   * @return each container's name, with the names of the containers it has a direct link to
   *     (sorted); sorted by name
   * @throws TRADENotAuthorizedException if a container refuses the principal
   * @throws TRADEException if a container cannot be asked
   */
  public Map<String, Collection<String>> getTRADEContainerGraph(String credentials)
      throws TRADEException {
    checkOpen();
    return core.admin().graph(credentials);
  }

  /**
   * The container graph with the round-trip time of each link, as each container measures it
   * (its middleware service {@code roundTrips}, called as {@code credentials}): the smoothed time
   * between a heartbeat probe it sends and its neighbour's echo. Ours; not in TRADE 1.1.1.
   *
   * @param credentials {@code <principal>:<secret>} of a principal that every container's access
   *     file lets call its middleware services
   * @return each container's name (sorted), with the names of the containers it has a direct
   *     link to and has measured (sorted), each with the round-trip time in microseconds; a link
   *     whose first probe has not been echoed yet is left out
   * @throws TRADENotAuthorizedException if a container refuses the principal
   * @throws TRADEException if a container cannot be asked
   */
  public Map<String, Map<String, Double>> getContainerRoundTrips(String credentials)
      throws TRADEException {
    checkOpen();
    return core.admin().roundTrips(credentials);
  }

  /**
   * Every container of the system as it describes itself ({@code describeContainer}, see
   * docs/middleware-services.md): id, name, host, addresses, uptime, services, links and their
   * round-trip times, and call statistics.
   *
   * @param credentials {@code <principal>:<secret>} that every container lets call its middleware
   *     services
   * @return one map per container, this one's first
   * @throws TRADENotAuthorizedException if a container refuses the principal
   * @throws TRADEException if a container cannot be asked
   */
  public List<Map<String, Object>> getContainers(String credentials) throws TRADEException {
    checkOpen();
    return core.admin().containers(credentials);
  }

  /**
   * Deregisters every service users registered in this container, as {@code credentials}; its
   * system services stay.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the call fails otherwise
   */
  public void reset(String credentials) throws TRADEException {
    admin(credentials, "reset", int.class);
  }

  /**
   * Shuts this container down, as {@code credentials}: it closes shortly after the call returns,
   * as {@link #close()} does.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if the call fails otherwise
   */
  public void shutdownTRADE(String credentials) throws TRADEException {
    admin(credentials, "shutdown", void.class);
  }

  /**
   * Applies a configuration to this running container, as {@code credentials}: the settings that
   * can change at run time take effect ({@code STARTDISCOVERY}, {@code STARTBROADCAST},
   * {@code CONNECTCONTAINERS} dialled once, and {@code SERVERIPS} listened on when
   * {@code STARTACCEPTINGCONNECTIONS=true}); every other key must equal the running setting.
   * Nothing changes when the configuration is refused.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param config a {@code trade.properties} stream; read to its end, not closed
   * @throws TRADEBadArgumentsException if the stream is not a valid configuration, or sets a key
   *     that only applies at start to another value (the message names the keys)
   * @throws TRADENotAuthorizedException if the principal may not
   * @throws TRADEException if applying a setting fails
   */
  public void loadConfig(String credentials, InputStream config) throws TRADEException {
    Objects.requireNonNull(config, "config == null");
    Properties p = new Properties();
    Map<String, String> now = core.settings().asMap();
    Map<String, String> wanted;
    try {
      p.load(config);
      wanted = Settings.defaults().withAll(p).asMap();
    } catch (IOException | IllegalArgumentException e) {
      throw new TRADEBadArgumentsException("loadConfig: " + e.getMessage());
    }
    List<String> fixed = new ArrayList<>();
    for (String key : p.stringPropertyNames()) {
      if (!RUNTIME_KEYS.contains(key) && !Objects.equals(now.get(key), wanted.get(key))) {
        fixed.add(key);
      }
    }
    if (!fixed.isEmpty()) {
      throw new TRADEBadArgumentsException("loadConfig: " + String.join(", ", fixed)
          + " only take effect when a container starts; leave them out, or build a new container");
    }
    if (p.containsKey("STARTDISCOVERY")) {
      setDiscovery(credentials, Boolean.parseBoolean(wanted.get("STARTDISCOVERY")));
    }
    if (p.containsKey("STARTBROADCAST")) {
      setBroadcast(credentials, Boolean.parseBoolean(wanted.get("STARTBROADCAST")));
    }
    if (Boolean.parseBoolean(wanted.get("STARTACCEPTINGCONNECTIONS"))
        && p.containsKey("SERVERIPS")) {
      for (String a : wanted.get("SERVERIPS").split(",")) {
        if (!a.isBlank()) {
          int at = a.lastIndexOf('@');
          startListenForConnections(credentials, a.substring(0, at).trim(),
              Integer.parseInt(a.substring(at + 1).trim()));
        }
      }
    }
    if (p.containsKey("CONNECTCONTAINERS")) {
      for (String a : wanted.get("CONNECTCONTAINERS").split(",")) {
        if (!a.isBlank()) {
          admin(credentials, "connect", void.class, a.trim());
        }
      }
    }
  }

  private static final Set<String> RUNTIME_KEYS = Set.of("STARTDISCOVERY", "STARTBROADCAST",
      "STARTACCEPTINGCONNECTIONS", "SERVERIPS", "CONNECTCONTAINERS");

  /**
   * Calls any service as {@code credentials}: with the proof of that principal, whatever this
   * container's own ({@code PRINCIPAL}). With the handle of another container's middleware service
   * (found with {@code inGroups("trade.system")}), it acts on that container.
   *
   * <pre>{@code
   * TRADEServiceInfo discovery = container.getAvailableService(new TRADEServiceConstraints()
   *     .inGroups("trade.system").name("setDiscovery").onHost("robot2"));
   * container.callAs("alice:" + secret, discovery, void.class, true);
   * }</pre>
   *
   * @param <T> the result's type
   * @param credentials {@code <principal>:<secret>}; anything else is anonymous
   * @param service the service to call
   * @param returnType as {@link TRADEServiceInfo#call(Class, Object...)}
   * @param args the arguments
   * @return the result
   * @throws TRADENotAuthorizedException if the service's container refuses the principal
   * @throws TRADEException as {@link TRADEServiceInfo#call(Class, Object...)}; a typed failure
   *     of a middleware service is thrown as itself
   */
  public <T> T callAs(String credentials, TRADEServiceInfo service, Class<T> returnType,
      Object... args) throws TRADEException {
    Objects.requireNonNull(service, "service == null");
    checkOpen();
    return core.admin().call(AdminClient.credentials(credentials), service.descriptor(), returnType,
        args);
  }

  /**
   * Gives {@code service} the groups {@code groups}: lookups in every container see the change.
   * A service of this container changes at once; a service of another container changes through
   * its middleware service {@code setServiceGroups}, called as this container's own principal
   * ({@code PRINCIPAL}), which that container's policy must allow.
   *
   * @param service the service; not null
   * @param groups its groups from now on; null or blank names are left out
   * @throws TRADERegistrationException if {@code groups} names the reserved group, or the service
   *     is a system service
   * @throws TRADEServiceNotFoundException if the service is not registered (any more)
   * @throws TRADENotAuthorizedException if the service's container refuses this container
   * @throws TRADEException if the call fails otherwise
   */
  public void setServiceGroups(TRADEServiceInfo service, Collection<String> groups)
      throws TRADEException {
    Objects.requireNonNull(service, "service == null");
    checkOpen();
    ServiceDescriptor d = service.descriptor();
    List<String> g = new ArrayList<>(normalize(groups));
    if (d.containerId().equals(core.containerId())) {
      if (d.groups().contains(dev.trade.internal.system.SystemGroup.NAME)) {
        throw new TRADERegistrationException("setServiceGroups: " + d.signature() + " is a system"
            + " service; its groups are fixed");
      }
      core.setGroups(d.serviceId(), g);
    } else {
      core.admin().call(core.settings().principal(), d.containerId(), "setServiceGroups",
          void.class, d.serviceId(), g);
    }
  }

  /**
   * Adds {@code groups} to the groups of {@code service}; see
   * {@link #setServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service; not null
   * @param groups the groups to add
   * @throws TRADEException as {@link #setServiceGroups(TRADEServiceInfo, Collection)}
   */
  public void addServiceGroups(TRADEServiceInfo service, Collection<String> groups)
      throws TRADEException {
    Set<String> g = new LinkedHashSet<>(current(service));
    g.addAll(normalize(groups));
    setServiceGroups(service, g);
  }

  /**
   * Removes {@code groups} from the groups of {@code service}; see
   * {@link #setServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service; not null
   * @param groups the groups to remove
   * @throws TRADEException as {@link #setServiceGroups(TRADEServiceInfo, Collection)}
   */
  public void removeServiceGroups(TRADEServiceInfo service, Collection<String> groups)
      throws TRADEException {
    Set<String> g = new LinkedHashSet<>(current(service));
    g.removeAll(normalize(groups));
    setServiceGroups(service, g);
  }

  /**
   * Removes every group of {@code service}: it is in no group afterwards. See
   * {@link #setServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service; not null
   * @throws TRADEException as {@link #setServiceGroups(TRADEServiceInfo, Collection)}
   */
  public void resetServiceGroups(TRADEServiceInfo service) throws TRADEException {
    setServiceGroups(service, List.of());
  }

  /** The groups of {@code service} as this container knows them now (the newest description). */
  private Set<String> current(TRADEServiceInfo service) {
    Objects.requireNonNull(service, "service == null");
    Entry e = core.registry().entry(service.descriptor());
    return (e == null ? service.descriptor() : e.descriptor()).groups();
  }

  private <T> T admin(String credentials, String name, Class<T> returnType, Object... args)
      throws TRADEException {
    checkOpen();
    return core.admin().call(credentials, core.containerId(), name, returnType, args);
  }

  /**
   * Deregisters every service of this container and disconnects it. Idempotent. Returns once
   * every connection is closed: at once, normally, and within about 2 s when a connected container
   * does not read (its connection is then closed without a goodbye).
   *
   * <p>Notifications of this container stop first: disconnecting makes every other container's
   * services unreachable from here, and reporting them as "left" to listeners that are closing
   * too would be false (they did not leave the system) and would call into components that are
   * shutting down.
   */
  @Override
  public void close() {
    proxies.close();
    core.close();
  }

  /**
   * A typed proxy: an implementation of {@code type} whose methods call the services of this
   * container's system with the same name and parameter types. See
   * {@link #proxy(Class, TRADEServiceConstraints)}.
   *
   * <pre>{@code
   * interface Arm {
   *   boolean openGripper(int speed);
   * }
   * Arm arm = container.proxy(Arm.class);
   * arm.openGripper(3);
   * }</pre>
   *
   * @param <T> the interface
   * @param type the interface to implement
   * @return the proxy, safe for concurrent use
   * @throws IllegalArgumentException if {@code type} is not an interface or one of its methods
   *     cannot stand for a service (the message names the method and the fix)
   */
  public <T> T proxy(Class<T> type) {
    return proxy(type, null);
  }

  /**
   * A typed proxy whose methods call services that also match {@code constraints} (for example
   * {@code inGroups("MyRobot")}).
   *
   * <p><b>Finding services.</b> Each abstract method {@code m(P1, P2)} calls the preferred service
   * (as {@link #getAvailableService} prefers) named {@code m} whose parameters take {@code P1, P2},
   * so overloads find their own services. The service is found on the method's first call and kept
   * while this container knows it; when it is deregistered or its container leaves, the next call
   * finds one again. Default methods run their own code; {@code equals}, {@code hashCode} and
   * {@code toString} are the proxy's own (identity).
   *
   * <p><b>Asynchronous methods.</b> A method returning {@code CompletableFuture<V>} (or
   * {@code CompletionStage<V>}) finds its service on the caller's thread and sends the call as
   * {@link TRADEServiceInfo#callAsync} does: it returns at once, and no thread waits while a remote
   * reply is outstanding. The future completes with the result, or fails with what the method
   * would have thrown (as below).
   *
   * <p><b>Failures.</b> A method that declares the exception the service threw (its own type, such
   * as {@code GripperJammedException}) throws that exception itself. Otherwise a method that
   * declares {@link TRADEException} throws it as {@link TRADEServiceInfo#call} would (for example
   * {@link TRADEServiceNotFoundException} when nothing matches); a method that does not gets an
   * {@link UncheckedTRADEException} whose cause is that {@code TRADEException}.
   *
   * <p>The interface is checked now, not on the first call; its parsed methods are cached for the
   * life of the class.
   *
   * @param <T> the interface
   * @param type the interface to implement
   * @param constraints what every method's service must also match; null for none; copied now
   * @return the proxy, safe for concurrent use
   * @throws IllegalArgumentException if {@code type} is not an interface or one of its methods
   *     cannot stand for a service (the message names the method and the fix)
   * @throws IllegalStateException if this container is closed
   */
  public <T> T proxy(Class<T> type, TRADEServiceConstraints constraints) {
    checkOpen();
    return proxies.create(type, constraints == null ? null : constraints.copy());
  }

  /** A service info for {@code d} whose calls go through this container. */
  TRADEServiceInfo bind(ServiceDescriptor d) {
    return new TRADEServiceInfo(d, core);
  }

  private List<TRADEServiceInfo> bindAll(List<Entry> entries, Class<?> annotation) {
    List<TRADEServiceInfo> infos = new ArrayList<>(entries.size());
    for (Entry e : entries) {
      if (annotation == null || hasAnnotation(e.descriptor(), annotation)) {
        infos.add(bind(e.descriptor()));
      }
    }
    return infos;
  }

  private static boolean hasAnnotation(ServiceDescriptor d, Class<?> type) {
    for (Annotation a : d.annotations()) {
      if (a.annotationType() == type) {
        return true;
      }
    }
    return false;
  }

  private void checkOpen() {
    if (core.isClosed()) {
      throw new IllegalStateException("container " + core.name() + " is closed");
    }
  }

  private static Set<String> normalize(Collection<String> groups) {
    Set<String> result = new LinkedHashSet<>();
    if (groups != null) {
      for (String g : groups) {
        if (g != null && !g.isBlank()) {
          result.add(g);
        }
      }
    }
    return result;
  }

  /**
   * Collects settings for a container. Starts from the built-in defaults; keys and values are those
   * of {@code trade.properties} (see docs/configuration.md). Not thread-safe; the container it
   * builds is.
   */
  public static final class Builder {
    private Settings settings = Settings.defaults();

    private Builder() {}

    /** A builder with these settings, unaffected by later changes to this one. */
    Builder copy() {
      Builder b = new Builder();
      b.settings = settings;
      return b;
    }

    /**
     * Starts over from the configuration TRADE would load for the default container: the file named
     * by the system property {@code trade.properties.path}, else by the environment variable
     * {@code TRADE_PROPERTIES_PATH}, else {@code trade.properties} in the working directory, else
     * {@code trade.properties} on the class path, else the defaults. Also applies TRADE's logging
     * file, as TRADE does: the one named by the system property {@code tradeLogging.config.path},
     * else by the environment variable {@code TRADE_LOGGING_CONFIG_PATH}, else
     * {@code tradeLogging.config} in the working directory (merged into the JVM's
     * {@code java.util.logging} configuration, once per file). See docs/configuration.md.
     *
     * @return this builder
     * @throws IllegalArgumentException if that configuration is invalid (the message names the key),
     *     or a file named by a system property or environment variable does not exist
     */
    public Builder loadConfiguration() {
      LoggingConfig.apply();
      settings = Settings.load();
      return this;
    }

    /**
     * Sets one setting.
     *
     * @param key a key of docs/configuration.md, such as {@code CONTAINERNAME}
     * @param value its value, as in a properties file
     * @return this builder
     * @throws IllegalArgumentException for an unknown key or a bad value (the message names both)
     */
    public Builder property(String key, String value) {
      settings = settings.with(Objects.requireNonNull(key, "key == null"),
          Objects.requireNonNull(value, "value == null"));
      return this;
    }

    /**
     * Sets every setting in {@code properties}, as {@link #property} does for each.
     *
     * @param properties keys and values
     * @return this builder
     * @throws IllegalArgumentException for an unknown key or a bad value (the message names both)
     */
    public Builder properties(Properties properties) {
      settings = settings.withAll(Objects.requireNonNull(properties, "properties == null"));
      return this;
    }

    /**
     * The container's name ({@code CONTAINERNAME}).
     *
     * @param name the name
     * @return this builder
     */
    public Builder name(String name) {
      return property("CONTAINERNAME", name);
    }

    /**
     * Strict mode ({@code COPYDATAFORLOCALINVOKES}): local calls copy mutable arguments and results,
     * so caller and provider never share a mutable object, as with remote calls.
     *
     * @param copy whether to copy
     * @return this builder
     */
    public Builder copyDataForLocalInvokes(boolean copy) {
      return property("COPYDATAFORLOCALINVOKES", Boolean.toString(copy));
    }

    /**
     * Builds the container and starts its networking when the settings ask for it.
     *
     * @return the container; close it when done
     * @throws java.io.UncheckedIOException if a listen address cannot be bound (the message names it)
     */
    public TRADEContainer build() {
      return new TRADEContainer(settings);
    }
  }
}
