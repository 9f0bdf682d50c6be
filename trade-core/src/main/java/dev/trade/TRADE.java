package dev.trade;

import java.io.InputStream;
import java.time.Duration;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.UUID;

/**
 * The JVM's default {@link TRADEContainer}, as static methods: the API TRADE users write against.
 *
 * <p>The default container is created on first use, from the configuration found by
 * {@link TRADEContainer.Builder#loadConfiguration()} (or, when the program set one first, from the
 * container or builder given to {@code setDefaultContainer}), and lives as long as the JVM: it is not
 * closed at exit, so that components' own shutdown hooks can still deregister through it (hooks
 * run at the same time, and one that closed it would make theirs fail); its links end with the
 * process, which its peers notice at once. Every method is safe to call from any thread.
 *
 * <pre>{@code
 * TRADE.registerAllServices(new RobotArm(), "MyRobot");
 * for (TRADEServiceInfo s : TRADE.getAvailableServices(new TRADEServiceConstraints().inGroups("MyRobot"))) {
 *   if (s.serviceString.equals("openGripper(int)")) {
 *     s.call(void.class, 3);
 *   }
 * }
 * }</pre>
 */
public final class TRADE {
  /**
   * The date (ISO 8601) of the last change to the API this class offers, as TRADE publishes the
   * date of its build: code can log which API it runs against.
   */
  public static final String lastmodified = "2026-12-04";

  private static final Object LOCK = new Object();
  private static volatile TRADEContainer defaultContainer;
  // Guarded by LOCK: what setDefaultContainer(Builder) asked for, until the first use builds it.
  private static TRADEContainer.Builder configured;

  private TRADE() {}

  /**
   * The default container, created now if this is the first use.
   *
   * @return the JVM's default container
   * @throws IllegalArgumentException if the configuration is invalid (the message names the key);
   *     the next call tries again
   */
  public static TRADEContainer getDefaultContainer() {
    TRADEContainer c = defaultContainer;
    if (c == null) {
      synchronized (LOCK) {
        c = defaultContainer;
        if (c == null) {
          c = configured != null ? configured.build()
              : TRADEContainer.builder().loadConfiguration().build();
          configured = null;
          defaultContainer = c;
        }
      }
    }
    return c;
  }

  /**
   * Makes {@code container} the default container, configured in code rather than by a file, a
   * system property or the environment. Call it before any other method of this class, first
   * thing in {@code main}:
   *
   * <pre>{@code
   * TRADE.setDefaultContainer(TRADEContainer.builder().name("arm")
   *     .property("CONNECTCONTAINERS", "10.0.0.2@10000").build());
   * }</pre>
   *
   * @param container the container the static methods use from now on; not null
   * @throws IllegalStateException if the default container exists already (the message says how
   *     to fix it)
   */
  public static void setDefaultContainer(TRADEContainer container) {
    Objects.requireNonNull(container, "container == null");
    synchronized (LOCK) {
      checkNotMade();
      defaultContainer = container;
    }
  }

  /**
   * Has the default container built from {@code builder} (its settings as they are now) at the
   * first use of this class, instead of from the configuration files; see
   * {@link #setDefaultContainer(TRADEContainer)}. A later call before the first use replaces an
   * earlier one.
   *
   * <pre>{@code
   * TRADE.setDefaultContainer(TRADEContainer.builder().loadConfiguration().name("arm"));
   * }</pre>
   *
   * @param builder the settings of the default container; not null; later changes to it do not
   *     count
   * @throws IllegalStateException if the default container exists already (the message says how
   *     to fix it)
   */
  public static void setDefaultContainer(TRADEContainer.Builder builder) {
    Objects.requireNonNull(builder, "builder == null");
    synchronized (LOCK) {
      checkNotMade();
      configured = builder.copy();
    }
  }

  private static void checkNotMade() {
    if (defaultContainer != null) {
      throw new IllegalStateException("the default container exists already (container "
          + defaultContainer.getName() + ", made by an earlier TRADE call or setDefaultContainer);"
          + " call TRADE.setDefaultContainer once, before any other TRADE method");
    }
  }

  static TRADEContainer defaultContainer() {
    return getDefaultContainer();
  }

  /**
   * Registers every service of {@code provider} in the default container: see
   * {@link TRADEContainer#registerAllServices(Object, Collection)}.
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link TRADEContainer#registerAllServices(Object, Collection)}
   */
  public static Collection<TRADEServiceInfo> registerAllServices(Object provider, Collection<String> groups)
      throws TRADEException {
    return getDefaultContainer().registerAllServices(provider, groups);
  }

  /**
   * Registers every service of {@code provider} in the default container:
   * {@code TRADE.registerAllServices(new RobotArm(), "MyRobot")}. See
   * {@link TRADEContainer#registerAllServices(Object, String...)}.
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link TRADEContainer#registerAllServices(Object, Collection)}
   */
  public static Collection<TRADEServiceInfo> registerAllServices(Object provider, String... groups)
      throws TRADEException {
    return getDefaultContainer().registerAllServices(provider, groups);
  }

  /**
   * The TRADE paper's name for registering with one group: see
   * {@link TRADEContainer#register(Object, String)}.
   *
   * @param provider the object whose methods become services; not null
   * @param group the group of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link TRADEContainer#registerAllServices(Object, Collection)}
   */
  public static Collection<TRADEServiceInfo> register(Object provider, String group) throws TRADEException {
    return getDefaultContainer().register(provider, group);
  }

  /**
   * The TRADE paper's name for {@link #registerAllServices(Object, Collection)}: see
   * {@link TRADEContainer#register(Object, Collection)}.
   *
   * @param provider the object whose methods become services; not null
   * @param groups the groups of its services; null for none
   * @return the registered services (empty when the object has no service methods)
   * @throws TRADEException as {@link TRADEContainer#registerAllServices(Object, Collection)}
   */
  public static Collection<TRADEServiceInfo> register(Object provider, Collection<String> groups)
      throws TRADEException {
    return getDefaultContainer().register(provider, groups);
  }

  /**
   * Removes every service of {@code provider} from the default container: see
   * {@link TRADEContainer#deregister(Object)}.
   *
   * @param provider an object registered in the default container
   * @throws TRADEException {@link TRADEServiceNotFoundException} if it is not registered there
   */
  public static void deregister(Object provider) throws TRADEException {
    getDefaultContainer().deregister(provider);
  }

  /**
   * The preferred service matching {@code constraints}: see
   * {@link TRADEContainer#getAvailableService(TRADEServiceConstraints)}.
   *
   * <pre>{@code
   * boolean opened = TRADE.getAvailableService(
   *     new TRADEServiceConstraints().name("openGripper").argTypes(int.class)).call(boolean.class, 3);
   * }</pre>
   *
   * @param constraints the constraints; null matches every service
   * @return the preferred matching service
   * @throws TRADEException {@link TRADEServiceNotFoundException} if none matches (the message
   *     names the constraints and the nearest services)
   */
  public static TRADEServiceInfo getAvailableService(TRADEServiceConstraints constraints)
      throws TRADEException {
    return getDefaultContainer().getAvailableService(constraints);
  }

  /**
   * Every service of the system: see {@link TRADEContainer#getAvailableServices()}.
   *
   * @return the services, in preference order; maybe none
   */
  public static Collection<TRADEServiceInfo> getAvailableServices() {
    return getDefaultContainer().getAvailableServices();
  }

  /**
   * Every service matching {@code constraints}: see
   * {@link TRADEContainer#getAvailableServices(TRADEServiceConstraints)}.
   *
   * @param constraints the constraints; null matches every service
   * @return the matches, in preference order; maybe none
   */
  public static Collection<TRADEServiceInfo> getAvailableServices(TRADEServiceConstraints constraints) {
    return getDefaultContainer().getAvailableServices(constraints);
  }

  /**
   * Asks the default container for a notification whose callback is a method of {@code listener}:
   * see {@link TRADEContainer#requestNotification(Object, String, Object, List, String)}.
   *
   * @param listener the object with the callback method; not null
   * @param type a notification type (docs/notifications.md): joined, left, once, after, at, every,
   *     if or when
   * @param argument what the type takes (constraints, a delay, an instant, a period), or null
   * @param services the service called or the condition, as {@code services[0]}; null or empty
   *     for types that take none
   * @param callbackMethod the name of the listener's callback method
   * @throws TRADEException {@link TRADEBadArgumentsException} for a bad request (nothing is
   *     scheduled then), {@link TRADEServiceUnavailableException} when the service's container
   *     is not reachable
   */
  public static void requestNotification(Object listener, String type, Object argument,
      List<TRADEServiceInfo> services, String callbackMethod) throws TRADEException {
    getDefaultContainer().requestNotification(listener, type, argument, services, callbackMethod);
  }

  /**
   * Asks for a notification whose callback is any service: see
   * {@link TRADEContainer#requestNotification(String, Object, List, TRADEServiceInfo)}.
   *
   * @param type a notification type
   * @param argument what the type takes, or null
   * @param services the service called or the condition, as {@code services[0]}; or null
   * @param callback the service called back
   * @return the notification's id, which {@link #cancelNotification(String)} cancels from any
   *     container
   * @throws TRADEException as {@link #requestNotification(Object, String, Object, List, String)}
   */
  public static String requestNotification(String type, Object argument,
      List<TRADEServiceInfo> services, TRADEServiceInfo callback) throws TRADEException {
    return getDefaultContainer().requestNotification(type, argument, services, callback);
  }

  /**
   * Cancels a listener's notifications: see
   * {@link TRADEContainer#cancelNotification(Object, String, Object)}.
   *
   * @param listener the listener of the requests
   * @param type their type
   * @param argument their argument; null for all of that type
   * @throws TRADEException if {@code type} is unknown
   */
  public static void cancelNotification(Object listener, String type, Object argument)
      throws TRADEException {
    getDefaultContainer().cancelNotification(listener, type, argument);
  }

  /**
   * Cancels a notification by its id, wherever it runs: see
   * {@link TRADEContainer#cancelNotification(String)}.
   *
   * @param id what {@link #requestNotification(String, Object, List, TRADEServiceInfo)} returned
   * @return whether it was live and is cancelled now
   * @throws TRADEException if the container that runs it cannot be reached
   */
  public static boolean cancelNotification(String id) throws TRADEException {
    return getDefaultContainer().cancelNotification(id);
  }

  /**
   * Calls back now for every matching service and later for every one that joins: see
   * {@link TRADEContainer#registerNotificationNowOrWhenJoined}.
   *
   * @param listener the object with the callback method; not null
   * @param constraints the services of interest (null: all)
   * @param callbackMethod the name of the callback method
   * @return the services matching now, in preference order
   * @throws TRADEException as {@link #requestNotification(Object, String, Object, List, String)}
   */
  public static Collection<TRADEServiceInfo> registerNotificationNowOrWhenJoined(Object listener,
      TRADEServiceConstraints constraints, String callbackMethod) throws TRADEException {
    return getDefaultContainer().registerNotificationNowOrWhenJoined(listener, constraints,
        callbackMethod);
  }

  /**
   * Waits for a matching service to be available: see {@link TRADEContainer#waitForService}.
   *
   * @param constraints the service wanted
   * @param timeout the longest to wait
   * @return the service, in preference order the first
   * @throws TRADEException {@link TRADETimeoutException} if none is available within
   *     {@code timeout}
   */
  public static TRADEServiceInfo waitForService(TRADEServiceConstraints constraints,
      Duration timeout) throws TRADEException {
    return getDefaultContainer().waitForService(constraints, timeout);
  }

  /**
   * Locks every service registered in all of {@code groups}, at once or not at all: see
   * {@link TRADEContainer#lockServicesContainAll(Collection)}.
   *
   * @param groups the groups every service to lock is in; not empty
   * @return the lock's id, or null when any of those services is held by another lock
   * @throws UncheckedTRADEException for bad input (no groups, no matching service) or an
   *     unreachable container; nothing is locked then
   */
  public static UUID lockServicesContainAll(Collection<String> groups) {
    return getDefaultContainer().lockServicesContainAll(groups);
  }

  /**
   * Locks every service registered in at least one of {@code groups}, at once or not at all: see
   * {@link TRADEContainer#lockServicesContainOne(Collection)}.
   *
   * @param groups the groups; a service in any of them is locked; not empty
   * @return the lock's id, or null when any of those services is held by another lock
   * @throws UncheckedTRADEException as {@link #lockServicesContainAll(Collection)}
   */
  public static UUID lockServicesContainOne(Collection<String> groups) {
    return getDefaultContainer().lockServicesContainOne(groups);
  }

  /**
   * Locks {@code services}, waiting up to {@code maxWait}: see
   * {@link TRADEContainer#lock(Collection, Duration)}.
   *
   * @param services the services to lock; not empty
   * @param maxWait the longest to wait for them; zero to take them only if free now
   * @return the lock, to release with {@link TRADELock#close()}
   * @throws TRADEException as {@link TRADEContainer#lock(Collection, Duration)}
   */
  public static TRADELock lock(Collection<TRADEServiceInfo> services, Duration maxWait)
      throws TRADEException {
    return getDefaultContainer().lock(services, maxWait);
  }

  /**
   * Releases a lock: see {@link TRADEContainer#releaseLock(UUID)}.
   *
   * @param lock the lock's id
   * @throws TRADEException {@link TRADEBadArgumentsException} if no lock of that id is held,
   *     {@link TRADENotAuthorizedException} if another container owns it
   */
  public static void releaseLock(UUID lock) throws TRADEException {
    getDefaultContainer().releaseLock(lock);
  }

  /**
   * Every lock's claims on services, from every container: see {@link TRADEContainer#getLocks()}.
   *
   * @return the claims; maybe none
   * @throws TRADEException as {@link TRADEContainer#getLocks()}
   */
  public static List<TRADELockInfo> getLocks() throws TRADEException {
    return getDefaultContainer().getLocks();
  }

  /**
   * Switches discovery of the default container on or off as {@code credentials}: see {@link TRADEContainer#setDiscovery(String, boolean)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param on whether to discover
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void setDiscovery(String credentials, boolean on) throws TRADEException {
    getDefaultContainer().setDiscovery(credentials, on);
  }

  /**
   * Switches announcing of the default container as {@code credentials}: see {@link TRADEContainer#setBroadcast(String, boolean)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param on whether to announce
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void setBroadcast(String credentials, boolean on) throws TRADEException {
    getDefaultContainer().setBroadcast(credentials, on);
  }

  /**
   * Asks for encryption on or off: see {@link TRADEContainer#setEncryption(String, boolean)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param on whether links should be encrypted
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void setEncryption(String credentials, boolean on) throws TRADEException {
    getDefaultContainer().setEncryption(credentials, on);
  }

  /**
   * Accepts connections on {@code ip@port} too: see {@link TRADEContainer#startListenForConnections(String, String, int)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param ip the address to listen on
   * @param port the port; 0 for any
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void startListenForConnections(String credentials, String ip, int port) throws TRADEException {
    getDefaultContainer().startListenForConnections(credentials, ip, port);
  }

  /**
   * Stops accepting connections: see {@link TRADEContainer#stopListenForConnections(String)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void stopListenForConnections(String credentials) throws TRADEException {
    getDefaultContainer().stopListenForConnections(credentials);
  }

  /**
   * Lets other containers call the default container's services, or stops them: see {@link TRADEContainer#accessToTRADEServices(String, boolean)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param allowed whether other containers may call
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void accessToTRADEServices(String credentials, boolean allowed) throws TRADEException {
    getDefaultContainer().accessToTRADEServices(credentials, allowed);
  }

  /**
   * Reads the network interfaces again: see {@link TRADEContainer#findInterfaces(String)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void findInterfaces(String credentials) throws TRADEException {
    getDefaultContainer().findInterfaces(credentials);
  }

  /**
   * The containers of the system and their links: see {@link TRADEContainer#getTRADEContainerGraph(String)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @return each container's name with the names of the containers it links to
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static Map<String, Collection<String>> getTRADEContainerGraph(String credentials) throws TRADEException {
    return getDefaultContainer().getTRADEContainerGraph(credentials);
  }

  /**
   * Deregisters every user's service of the default container: see {@link TRADEContainer#reset(String)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void reset(String credentials) throws TRADEException {
    getDefaultContainer().reset(credentials);
  }

  /**
   * Shuts the default container down: see {@link TRADEContainer#shutdownTRADE(String)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void shutdownTRADE(String credentials) throws TRADEException {
    getDefaultContainer().shutdownTRADE(credentials);
  }

  /**
   * Applies a configuration to the running default container: see {@link TRADEContainer#loadConfig(String, InputStream)}.
   *
   * @param credentials {@code <principal>:<secret>}
   * @param config a {@code trade.properties} stream
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void loadConfig(String credentials, InputStream config) throws TRADEException {
    getDefaultContainer().loadConfig(credentials, config);
  }

  /**
   * Gives a service other groups, everywhere: see {@link TRADEContainer#setServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service
   * @param groups its groups from now on
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void setServiceGroups(TRADEServiceInfo service, Collection<String> groups) throws TRADEException {
    getDefaultContainer().setServiceGroups(service, groups);
  }

  /**
   * Adds groups to a service: see {@link TRADEContainer#addServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service
   * @param groups the groups to add
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void addServiceGroups(TRADEServiceInfo service, Collection<String> groups) throws TRADEException {
    getDefaultContainer().addServiceGroups(service, groups);
  }

  /**
   * Removes groups from a service: see {@link TRADEContainer#removeServiceGroups(TRADEServiceInfo, Collection)}.
   *
   * @param service the service
   * @param groups the groups to remove
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void removeServiceGroups(TRADEServiceInfo service, Collection<String> groups) throws TRADEException {
    getDefaultContainer().removeServiceGroups(service, groups);
  }

  /**
   * Removes every group of a service: see {@link TRADEContainer#resetServiceGroups(TRADEServiceInfo)}.
   *
   * @param service the service
   * @throws TRADEException {@link TRADENotAuthorizedException} if the principal may not, or
   *     another failure of the operation
   */
  public static void resetServiceGroups(TRADEServiceInfo service) throws TRADEException {
    getDefaultContainer().resetServiceGroups(service);
  }

  /**
   * Calls {@code wrapper} before every call of {@code target}, system-wide: see
   * {@link TRADEContainer#beforeService(TRADEServiceInfo, TRADEServiceInfo)}.
   *
   * @param wrapper the service called before the target; it takes one {@code Object[]}:
   *     {@code [serviceName, arg1, ..., argN]}
   * @param target the service instrumented, of any container
   * @throws TRADEException as {@link TRADEContainer#beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public static void beforeService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    getDefaultContainer().beforeService(wrapper, target);
  }

  /**
   * Calls {@code wrapper} after every call of {@code target}, system-wide: see
   * {@link TRADEContainer#afterService(TRADEServiceInfo, TRADEServiceInfo)}.
   *
   * @param wrapper the service called after the target; it takes one {@code Object[]}:
   *     {@code [serviceName, arg1, ..., argN, result]}
   * @param target the service instrumented, of any container
   * @throws TRADEException as {@link TRADEContainer#beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public static void afterService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    getDefaultContainer().afterService(wrapper, target);
  }

  /**
   * An after hook whose wrapper the caller may not wait for: see
   * {@link TRADEContainer#afterService(TRADEServiceInfo, TRADEServiceInfo, boolean)}.
   *
   * @param wrapper the service called after the target
   * @param target the service instrumented, of any container
   * @param asynchronous whether the caller's result does not wait for the wrapper
   * @throws TRADEException as {@link TRADEContainer#beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public static void afterService(TRADEServiceInfo wrapper, TRADEServiceInfo target,
      boolean asynchronous) throws TRADEException {
    getDefaultContainer().afterService(wrapper, target, asynchronous);
  }

  /**
   * The TRADE paper's form of {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}: see
   * {@link TRADEContainer#beforeService(String, String[], TRADEServiceConstraints, String,
   * String[], TRADEServiceConstraints)}.
   *
   * @param wrapperName the wrapper's name
   * @param wrapperArgTypeNames the wrapper's parameter type names; null: any
   * @param wrapperConstraints what the wrapper must also match; null: nothing more
   * @param targetName the target's name
   * @param targetArgTypeNames the target's parameter type names; null: any
   * @param targetConstraints what the target must also match; null: nothing more
   * @throws TRADEException {@link TRADEServiceNotFoundException} when no service matches a
   *     description; otherwise as {@link #beforeService(TRADEServiceInfo, TRADEServiceInfo)}
   */
  public static void beforeService(String wrapperName, String[] wrapperArgTypeNames,
      TRADEServiceConstraints wrapperConstraints, String targetName, String[] targetArgTypeNames,
      TRADEServiceConstraints targetConstraints) throws TRADEException {
    getDefaultContainer().beforeService(wrapperName, wrapperArgTypeNames, wrapperConstraints,
        targetName, targetArgTypeNames, targetConstraints);
  }

  /**
   * The TRADE paper's form of {@link #afterService(TRADEServiceInfo, TRADEServiceInfo)}:
   * {@code TRADE.afterService("addObservedOutput", new String[] {Object[].class.getName()},
   * new TRADEServiceConstraints(), serviceName, serviceArgsClasses, constraints)}.
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
  public static void afterService(String wrapperName, String[] wrapperArgTypeNames,
      TRADEServiceConstraints wrapperConstraints, String targetName, String[] targetArgTypeNames,
      TRADEServiceConstraints targetConstraints) throws TRADEException {
    getDefaultContainer().afterService(wrapperName, wrapperArgTypeNames, wrapperConstraints,
        targetName, targetArgTypeNames, targetConstraints);
  }

  /**
   * Removes a before hook: see {@link TRADEContainer#removeBeforeService}.
   *
   * @param wrapper the hook's wrapper
   * @param target the hook's target
   * @return whether there was such a hook
   * @throws TRADEException if the target's container cannot be reached
   */
  public static boolean removeBeforeService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    return getDefaultContainer().removeBeforeService(wrapper, target);
  }

  /**
   * Removes an after hook: see {@link TRADEContainer#removeAfterService}.
   *
   * @param wrapper the hook's wrapper
   * @param target the hook's target
   * @return whether there was such a hook
   * @throws TRADEException if the target's container cannot be reached
   */
  public static boolean removeAfterService(TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    return getDefaultContainer().removeAfterService(wrapper, target);
  }

  /**
   * Hooks {@code wrapper} before every service matching {@code targets}, including those that join
   * later: see {@link TRADEContainer#beforeServices}.
   *
   * @param wrapper the service called before each target
   * @param targets the services to instrument
   * @return how many services it covers now
   * @throws TRADEException as {@link TRADEContainer#beforeServices}
   */
  public static int beforeServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    return getDefaultContainer().beforeServices(wrapper, targets);
  }

  /**
   * Hooks {@code wrapper} after every service matching {@code targets}, including those that join
   * later: see {@link TRADEContainer#afterServices(TRADEServiceInfo, TRADEServiceConstraints)}.
   *
   * @param wrapper the service called after each target
   * @param targets the services to instrument
   * @return how many services it covers now
   * @throws TRADEException as {@link TRADEContainer#beforeServices}
   */
  public static int afterServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets)
      throws TRADEException {
    return getDefaultContainer().afterServices(wrapper, targets);
  }

  /**
   * As {@link #afterServices(TRADEServiceInfo, TRADEServiceConstraints)}, asynchronous if asked:
   * see {@link TRADEContainer#afterServices(TRADEServiceInfo, TRADEServiceConstraints, boolean)}.
   *
   * @param wrapper the service called after each target
   * @param targets the services to instrument
   * @param asynchronous whether callers' results do not wait for the wrapper
   * @return how many services it covers now
   * @throws TRADEException as {@link TRADEContainer#beforeServices}
   */
  public static int afterServices(TRADEServiceInfo wrapper, TRADEServiceConstraints targets,
      boolean asynchronous) throws TRADEException {
    return getDefaultContainer().afterServices(wrapper, targets, asynchronous);
  }

  /**
   * Removes a set of before hooks: see {@link TRADEContainer#removeBeforeServices}.
   *
   * @param wrapper the set's wrapper
   * @param targets the set's constraints
   * @return whether there was such a set
   * @throws TRADEException if the wrapper is not a service info
   */
  public static boolean removeBeforeServices(TRADEServiceInfo wrapper,
      TRADEServiceConstraints targets) throws TRADEException {
    return getDefaultContainer().removeBeforeServices(wrapper, targets);
  }

  /**
   * Removes a set of after hooks: see {@link TRADEContainer#removeAfterServices}.
   *
   * @param wrapper the set's wrapper
   * @param targets the set's constraints
   * @return whether there was such a set
   * @throws TRADEException if the wrapper is not a service info
   */
  public static boolean removeAfterServices(TRADEServiceInfo wrapper,
      TRADEServiceConstraints targets) throws TRADEException {
    return getDefaultContainer().removeAfterServices(wrapper, targets);
  }

  /**
   * The hooks of every container known to the default container: see
   * {@link TRADEContainer#getHooks()}.
   *
   * @return one map per hook
   */
  public static List<Map<String, Object>> getHooks() {
    return getDefaultContainer().getHooks();
  }

  /**
   * Starts the default container's call log: see {@link TRADEContainer#startCallLog}.
   *
   * @param file the file to append JSON lines to
   * @param groups the groups whose services are logged; none: all
   * @return the file's absolute path
   * @throws TRADEException as {@link TRADEContainer#startCallLog}
   */
  public static String startCallLog(String file, String... groups) throws TRADEException {
    return getDefaultContainer().startCallLog(file, groups);
  }

  /**
   * Stops the default container's call log: see {@link TRADEContainer#stopCallLog}.
   *
   * @return whether one ran
   * @throws TRADEException as {@link TRADEContainer#stopCallLog}
   */
  public static boolean stopCallLog() throws TRADEException {
    return getDefaultContainer().stopCallLog();
  }

  /**
   * The call statistics of every container known to the default container: see
   * {@link TRADEContainer#getCallStatistics()}.
   *
   * @return one map per service
   */
  public static List<Map<String, Object>> getCallStatistics() {
    return getDefaultContainer().getCallStatistics();
  }

  /**
   * Switches discovery on or off: see {@link TRADEContainer#setDiscovery(boolean)}.
   *
   * @param on whether to discover
   */
  public static void setDiscovery(boolean on) {
    getDefaultContainer().setDiscovery(on);
  }

  /**
   * Switches announcing on or off: see {@link TRADEContainer#setBroadcast(boolean)}.
   *
   * @param on whether to announce
   */
  public static void setBroadcast(boolean on) {
    getDefaultContainer().setBroadcast(on);
  }

  /**
   * Every service matching {@code constraints} whose method carries {@code annotation}: see
   * {@link TRADEContainer#getAvailableServices(Class, TRADEServiceConstraints)}.
   *
   * @param annotation the annotation type; not null
   * @param constraints the constraints; null matches every service
   * @return the matches, in preference order; maybe none
   */
  public static Collection<TRADEServiceInfo> getAvailableServices(
      Class<?> annotation, TRADEServiceConstraints constraints) {
    return getDefaultContainer().getAvailableServices(annotation, constraints);
  }

  /**
   * A typed proxy on the default container: see {@link TRADEContainer#proxy(Class)}.
   *
   * <pre>{@code
   * interface Arm {
   *   boolean openGripper(int speed) throws TRADEException;
   * }
   * boolean opened = TRADE.proxy(Arm.class).openGripper(3);
   * }</pre>
   *
   * @param <T> the interface
   * @param type the interface to implement
   * @return the proxy, safe for concurrent use
   * @throws IllegalArgumentException if {@code type} is not an interface or one of its methods
   *     cannot stand for a service (the message names the method and the fix)
   */
  public static <T> T proxy(Class<T> type) {
    return getDefaultContainer().proxy(type);
  }

  /**
   * A typed proxy on the default container whose services also match {@code constraints}: see
   * {@link TRADEContainer#proxy(Class, TRADEServiceConstraints)}.
   *
   * @param <T> the interface
   * @param type the interface to implement
   * @param constraints what every method's service must also match; null for none
   * @return the proxy, safe for concurrent use
   * @throws IllegalArgumentException if {@code type} is not an interface or one of its methods
   *     cannot stand for a service (the message names the method and the fix)
   */
  public static <T> T proxy(Class<T> type, TRADEServiceConstraints constraints) {
    return getDefaultContainer().proxy(type, constraints);
  }
}
