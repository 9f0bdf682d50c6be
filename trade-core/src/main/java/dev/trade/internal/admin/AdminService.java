package dev.trade.internal.admin;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import dev.trade.internal.config.PeerAddress;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.system.SystemGroup;
import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;

/**
 * The middleware's own operations as system services, one per container in the reserved group
 * (docs/middleware-services.md names each, with its parameter and return types): discovery and
 * announcing, listening and links, the description of this container, providers started by class
 * name, service groups, and shutting down. Calls to it pass the host chain like any call, so the
 * access link's policy applies: by default only the role {@code admin} may call it.
 *
 * <p>Public only because services must be; the module does not export it. Safe for concurrent use.
 */
public final class AdminService {
  /** What the service acts on: its container. */
  public interface Container {
    String id();

    String name();

    String host();

    void setDiscovery(boolean on);

    void setBroadcast(boolean on);

    boolean isDiscovering();

    boolean isBroadcasting();

    boolean usesEncryption();

    /** Accepts connections on {@code address} too; returns the address bound. */
    InetSocketAddress listen(InetSocketAddress address) throws IOException;

    List<InetSocketAddress> stopListening();

    List<InetSocketAddress> listenAddresses();

    /** The addresses it would announce now (wildcards expanded to the interfaces up now). */
    List<InetSocketAddress> announceable();

    void connect(InetSocketAddress address);

    boolean disconnect(UUID container);

    List<String> neighbours();

    /** The smoothed round-trip time of each direct link measured so far, in ns, by peer id. */
    Map<String, Long> roundTrips();

    /** This container's call statistics (the call log service's {@code callStatistics}). */
    List<Map<String, Object>> callStatistics();

    /** This container's own services, the reserved group's included. */
    List<LocalService> services();

    List<LocalService> register(Object provider, Set<String> groups) throws TRADEException;

    void deregister(Object provider) throws TRADEException;

    /** Deregisters every provider registered by users (not the system's). */
    int reset();

    void setGroups(long serviceId, Set<String> groups) throws TRADEException;

    /** Closes the container soon after this call has replied. */
    void shutdownSoon();
  }

  private final Container container;
  private final Access access;
  private final List<String> allowedClasses;
  private final long startedMillis;
  // Guarded by this: providers started through startProvider, by class name.
  private final Map<String, List<Object>> started = new LinkedHashMap<>();

  /** @param allowedClasses PROVIDERCLASSES: the classes startProvider may instantiate */
  public AdminService(Container container, Access access, List<String> allowedClasses,
      long startedMillis) {
    this.container = Objects.requireNonNull(container, "container == null");
    this.access = Objects.requireNonNull(access, "access == null");
    this.allowedClasses = List.copyOf(allowedClasses);
    this.startedMillis = startedMillis;
  }

  /** Switches multicast discovery of other containers on or off. */
  @TRADEService
  public void setDiscovery(boolean on) {
    container.setDiscovery(on);
  }

  /** Switches announcing this container by multicast on or off (on also listens). */
  @TRADEService
  public void setBroadcast(boolean on) {
    container.setBroadcast(on);
  }

  /**
   * Encryption is chosen per link at its handshake from USEENCRYPTION, and cannot change while
   * the container runs: asking for the setting it has succeeds, asking for the other fails.
   */
  @TRADEService
  public void setEncryption(boolean on) throws TRADEBadArgumentsException {
    if (on != container.usesEncryption()) {
      throw new TRADEBadArgumentsException("setEncryption(" + on + "): container "
          + container.name() + " runs with USEENCRYPTION=" + container.usesEncryption()
          + ", which is fixed when a container starts; set USEENCRYPTION=" + on
          + " in its configuration and restart it");
    }
  }

  /**
   * Whether calls from other containers reach this container's ordinary services (system services
   * stay under their policy either way, so an administrator can switch it back).
   */
  @TRADEService
  public void setRemoteAccess(boolean open) {
    access.setRemoteAccess(open);
  }

  /**
   * Accepts connections on {@code ip} and {@code port} (0: any free port) too.
   *
   * @return the address bound, as {@code ip@port}
   */
  @TRADEService
  public String startListenForConnections(String ip, int port) throws IOException {
    PeerAddress a = new PeerAddress(Objects.requireNonNull(ip, "ip == null"), port);
    return text(container.listen(new InetSocketAddress(a.host(), a.port())));
  }

  /** Stops accepting connections (links already made stay); returns the addresses closed. */
  @TRADEService
  public List<String> stopListenForConnections() {
    return texts(container.stopListening());
  }

  /**
   * Reads the network interfaces again: the addresses this container accepts connections on, a
   * wildcard expanded to the interfaces that are up now, as {@code ip@port}; while it announces,
   * it announces them now.
   */
  @TRADEService
  public List<String> findInterfaces() {
    List<String> result = texts(container.announceable());
    if (container.isBroadcasting()) {
      container.setBroadcast(true); // announces at once
    }
    return result;
  }

  /** Dials the container at {@code address} ({@code ip@port}) once. */
  @TRADEService
  public void connect(String address) {
    PeerAddress a = PeerAddress.parse(Objects.requireNonNull(address, "address == null"));
    container.connect(new InetSocketAddress(a.host(), a.port()));
  }

  /** Closes the direct link to the container with id {@code containerId}; false if none. */
  @TRADEService
  public boolean disconnect(String containerId) {
    return container.disconnect(UUID.fromString(containerId));
  }

  /** The ids of the containers this one has a direct link to. */
  @TRADEService
  public List<String> neighbours() {
    return List.copyOf(container.neighbours());
  }

  /**
   * The smoothed round-trip time of each direct link whose peer has echoed a heartbeat probe, in
   * microseconds, by the peer's id (links not measured yet are left out).
   */
  @TRADEService
  public Map<String, Double> roundTrips() {
    Map<String, Double> result = new TreeMap<>();
    container.roundTrips().forEach((id, nanos) -> result.put(id, nanos / 1000.0));
    return result;
  }

  /**
   * This container: {@code id}, {@code name}, {@code host} (String), {@code addresses} (its listen
   * addresses as {@code ip@port}), {@code uptimeMillis} (Long), {@code services} (its services'
   * signatures with their groups, the reserved group's included), {@code links} (its neighbours'
   * ids), {@code roundTripMicros} (as {@link #roundTrips}), {@code discovering} and
   * {@code broadcasting} (Boolean), {@code statistics} (per service calls, failures and latency,
   * as the call log service's {@code callStatistics}: empty unless they are or were switched on).
   */
  @TRADEService
  public Map<String, Object> describeContainer() {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("id", container.id());
    m.put("name", container.name());
    m.put("host", container.host());
    m.put("addresses", texts(container.listenAddresses()));
    m.put("uptimeMillis", Math.max(0, System.currentTimeMillis() - startedMillis));
    List<String> services = new ArrayList<>();
    for (LocalService s : container.services()) {
      services.add(s.descriptor().signature() + " " + s.descriptor().groups());
    }
    m.put("services", services);
    m.put("links", List.copyOf(container.neighbours()));
    m.put("roundTripMicros", roundTrips());
    m.put("discovering", container.isDiscovering());
    m.put("broadcasting", container.isBroadcasting());
    m.put("statistics", container.callStatistics());
    return m;
  }

  /**
   * Registers a new instance of {@code className} (public, with a public no-argument
   * constructor, on this container's class path and allowed by PROVIDERCLASSES) in
   * {@code groups}.
   *
   * @return the signatures of the services registered
   * @throws TRADERegistrationException naming the class and what to change
   */
  @TRADEService
  public List<String> startProvider(String className, List<String> groups) throws TRADEException {
    Objects.requireNonNull(className, "className == null");
    if (!allowed(className)) {
      throw new TRADERegistrationException("startProvider: class " + className + " is not allowed"
          + " in container " + container.name() + "; add it (or its package, pkg.*) to that"
          + " container's PROVIDERCLASSES");
    }
    Set<String> g = new LinkedHashSet<>(groups == null ? List.of() : groups);
    SystemGroup.refuse(g);
    Object provider = instantiate(className);
    List<String> signatures = new ArrayList<>();
    for (LocalService s : container.register(provider, g)) {
      signatures.add(s.descriptor().signature());
    }
    synchronized (this) {
      started.computeIfAbsent(className, k -> new ArrayList<>()).add(provider);
    }
    return signatures;
  }

  /**
   * Deregisters every provider of {@code className} that {@link #startProvider} started here.
   *
   * @return how many were deregistered
   */
  @TRADEService
  public int stopProvider(String className) throws TRADEException {
    List<Object> providers;
    synchronized (this) {
      providers = started.remove(className);
    }
    if (providers == null) {
      return 0;
    }
    for (Object p : providers) {
      container.deregister(p);
    }
    return providers.size();
  }

  /**
   * Gives this container's service {@code serviceId} the groups {@code groups}: lookups in every
   * container see the change. The reserved group can be neither given nor taken.
   */
  @TRADEService
  public void setServiceGroups(long serviceId, List<String> groups) throws TRADEException {
    Set<String> g = new LinkedHashSet<>(groups == null ? List.of() : groups);
    g.removeIf(x -> x == null || x.isBlank());
    SystemGroup.refuse(g);
    for (LocalService s : container.services()) {
      if (s.descriptor().serviceId() == serviceId
          && s.descriptor().groups().contains(SystemGroup.NAME)) {
        throw new TRADERegistrationException("setServiceGroups: " + s.descriptor().signature()
            + " is a system service of container " + container.name() + "; its groups are fixed");
      }
    }
    container.setGroups(serviceId, g);
  }

  /**
   * Deregisters every provider users registered in this container (its system services stay).
   *
   * @return how many providers were deregistered
   */
  @TRADEService
  public int reset() {
    synchronized (this) {
      started.clear();
    }
    return container.reset();
  }

  /** Closes this container shortly after replying: its services leave every container's table. */
  @TRADEService
  public void shutdown() {
    container.shutdownSoon();
  }

  private boolean allowed(String className) {
    for (String p : allowedClasses) {
      if (p.equals(className)
          || p.endsWith(".**") && className.startsWith(p.substring(0, p.length() - 2))
          || p.endsWith(".*") && className.startsWith(p.substring(0, p.length() - 1))
              && className.indexOf('.', p.length() - 1) < 0) {
        return true;
      }
    }
    return false;
  }

  private static Object instantiate(String className) throws TRADERegistrationException {
    try {
      Class<?> c = Class.forName(className, true, loader());
      if (!Modifier.isPublic(c.getModifiers()) || c.isInterface()
          || Modifier.isAbstract(c.getModifiers())) {
        throw new TRADERegistrationException("startProvider: class " + className + " must be a"
            + " public, concrete class with a public no-argument constructor");
      }
      Constructor<?> k = c.getConstructor();
      return k.newInstance();
    } catch (ClassNotFoundException e) {
      throw new TRADERegistrationException("startProvider: class " + className + " is not on the"
          + " class path of this container; add its jar there");
    } catch (NoSuchMethodException | IllegalAccessException | InstantiationException e) {
      throw new TRADERegistrationException("startProvider: class " + className + " has no public"
          + " no-argument constructor; add one");
    } catch (InvocationTargetException e) {
      throw new TRADERegistrationException("startProvider: the constructor of " + className
          + " threw " + e.getCause(), e.getCause());
    }
  }

  private static ClassLoader loader() {
    ClassLoader l = Thread.currentThread().getContextClassLoader();
    return l != null ? l : AdminService.class.getClassLoader();
  }

  private static String text(InetSocketAddress a) {
    String ip = a.getAddress().getHostAddress();
    return (ip.contains(":") ? "[" + ip + "]" : ip) + "@" + a.getPort();
  }

  private static List<String> texts(List<InetSocketAddress> list) {
    List<String> result = new ArrayList<>();
    for (InetSocketAddress a : list) {
      result.add(text(a));
    }
    return result;
  }

  @Override
  public String toString() {
    return "AdminService[" + container.name() + "]";
  }

}
