package dev.trade;

import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.config.LoggingConfig;
import dev.trade.internal.config.Settings;
import dev.trade.internal.container.ContainerCore;
import dev.trade.internal.notify.Notifications;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.annotation.Annotation;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Properties;
import java.util.Set;

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
  private final Notifications notifications;

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
    });
    this.notifications = new Notifications(core.registry(), TRADEServiceInfo.class, this::bind,
        core.name());
  }

  /** A builder starting from the built-in defaults (no configuration file is read). */
  public static Builder builder() {
    return new Builder();
  }

  /** This container's name (the {@code CONTAINERNAME} setting, or one derived from host and pid). */
  public String getName() {
    return core.name();
  }

  /** The id of this container's incarnation: unique, new at every start. */
  public String getId() {
    return core.containerId();
  }

  /** The host name this container reports for its services. */
  public String getHost() {
    return core.host();
  }

  /**
   * Registers every {@link TRADEService} method of {@code provider} as a service in
   * {@code groups}; null, empty or blank group names mean no group. All or nothing.
   *
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

  /** As {@link #registerAllServices(Object, Collection)}; {@code (String) null} means no group. */
  public Collection<TRADEServiceInfo> registerAllServices(Object provider, String... groups)
      throws TRADEException {
    return registerAllServices(provider, groups == null ? List.of() : Arrays.asList(groups));
  }

  /** The TRADE paper's name for {@link #registerAllServices(Object, String...)} with one group. */
  public Collection<TRADEServiceInfo> register(Object provider, String group) throws TRADEException {
    return registerAllServices(provider, group);
  }

  /** The TRADE paper's name for {@link #registerAllServices(Object, Collection)}. */
  public Collection<TRADEServiceInfo> register(Object provider, Collection<String> groups)
      throws TRADEException {
    return registerAllServices(provider, groups);
  }

  /**
   * Removes every service of {@code provider}. Calls already running finish; later calls through
   * existing infos fail with {@link TRADEServiceUnavailableException}.
   *
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
   * @param constraints null matches every service
   * @throws TRADEServiceNotFoundException if none matches; the message names the constraints
   */
  public TRADEServiceInfo getAvailableService(TRADEServiceConstraints constraints)
      throws TRADEException {
    checkOpen();
    TRADEServiceConstraints c = constraints == null ? new TRADEServiceConstraints() : constraints;
    Entry e = core.registry().findFirst(c.requiredName(), c.toQuery());
    if (e == null) {
      throw new TRADEServiceNotFoundException("No service matches " + c);
    }
    return bind(e.descriptor());
  }

  /** Every service of the system, in preference order. */
  public Collection<TRADEServiceInfo> getAvailableServices() {
    return getAvailableServices(null);
  }

  /** Every service matching {@code constraints} (null: all), in preference order; maybe none. */
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
   * actually chosen), as {@code ip@port}. Empty when it does not accept connections.
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
   * Asks for {@code listener.callbackMethod(TRADEServiceInfo)} to be called for every service
   * matching {@code constraints} that becomes available ({@code "joined"}) or goes away
   * ({@code "left"}) anywhere in the system from now on: registered or deregistered locally, or in
   * a container that joins, leaves or dies. The callback must be a public {@code @TRADEService}
   * method taking one {@code TRADEServiceInfo}: callbacks are services.
   *
   * <p>Callbacks run on one delivery thread of this container, one event at a time, in the order
   * the changes happened; each event reaches each matching request once. A callback that throws is
   * logged and does not stop later deliveries.
   *
   * @param constraints the services of interest (null: all)
   * @param argument reserved for notification types that take one; ignored by joined and left
   * @throws TRADEBadArgumentsException an unknown type, or no usable callback method (the message
   *     names the class and method and what is wrong)
   */
  public void requestNotification(Object listener, String type, TRADEServiceConstraints constraints,
      Object argument, String callbackMethod) throws TRADEException {
    checkOpen();
    notifications.request(listener, type, query(constraints), callbackMethod);
  }

  /**
   * Cancels the listener's notifications of {@code type} whose constraints equal
   * {@code constraints}, or all of that type when {@code constraints} is null. Events already
   * queued for a cancelled request are not delivered.
   */
  public void cancelNotification(Object listener, String type, TRADEServiceConstraints constraints)
      throws TRADEException {
    notifications.cancel(listener, type, constraints == null ? null : constraints.toQuery());
  }

  /**
   * Calls {@code listener.callbackMethod(TRADEServiceInfo)} now for every service already matching
   * {@code constraints}, and then for every one that joins: without a race between the two, so
   * each service is delivered exactly once.
   */
  public void registerNotificationNowOrWhenJoined(Object listener,
      TRADEServiceConstraints constraints, String callbackMethod) throws TRADEException {
    checkOpen();
    notifications.requestNowOrWhenJoined(listener, query(constraints), callbackMethod);
  }

  private static Query query(TRADEServiceConstraints constraints) {
    return (constraints == null ? new TRADEServiceConstraints() : constraints).toQuery();
  }

  /**
   * Switches multicast discovery on or off at run time: while on, this container listens for the
   * announcements of containers of its system ({@code TRADESYSID}, {@code CREDENTIALS}) and connects
   * to them. See docs/discovery.md.
   *
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
   * @throws java.io.UncheckedIOException if a socket cannot be opened
   */
  public void setBroadcast(boolean on) {
    checkOpen();
    core.setBroadcast(on);
  }

  /** Whether discovery is on. */
  public boolean isDiscovering() {
    return core.isDiscovering();
  }

  /** Whether this container announces itself. */
  public boolean isBroadcasting() {
    return core.isBroadcasting();
  }

  /**
   * The ids of the containers this one has a direct, authenticated link to right now: an
   * unmodifiable snapshot.
   */
  public List<String> getNeighbours() {
    return core.neighbours();
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
    notifications.close();
    core.close();
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
     * @throws IllegalArgumentException for an unknown key or a bad value (the message names both)
     */
    public Builder property(String key, String value) {
      settings = settings.with(Objects.requireNonNull(key, "key == null"),
          Objects.requireNonNull(value, "value == null"));
      return this;
    }

    /** Sets every setting in {@code properties}, as {@link #property} does for each. */
    public Builder properties(Properties properties) {
      settings = settings.withAll(Objects.requireNonNull(properties, "properties == null"));
      return this;
    }

    /** The container's name ({@code CONTAINERNAME}). */
    public Builder name(String name) {
      return property("CONTAINERNAME", name);
    }

    /**
     * Strict mode ({@code COPYDATAFORLOCALINVOKES}): local calls copy mutable arguments and results,
     * so caller and provider never share a mutable object, as with remote calls.
     */
    public Builder copyDataForLocalInvokes(boolean copy) {
      return property("COPYDATAFORLOCALINVOKES", Boolean.toString(copy));
    }

    /**
     * Builds the container and starts its networking when the settings ask for it.
     *
     * @throws java.io.UncheckedIOException if a listen address cannot be bound (the message names it)
     */
    public TRADEContainer build() {
      return new TRADEContainer(settings);
    }
  }
}
