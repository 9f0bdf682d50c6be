package dev.trade.internal.admin;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * The static API's side of the middleware services: it finds the {@link AdminService} of the
 * container an operation acts on and calls it like any service, with the proof of the caller's
 * credentials in the call's context; it never reaches around the call path. Safe for concurrent
 * use.
 */
public final class AdminClient {
  private static final Query SYSTEM = new Query(null, null, null, Set.of(SystemGroup.NAME), Set.of(),
      false, null, null, Set.of(), List.of(), List.of());

  /** How a call with a context is made (this container's caller half). */
  public interface Calls {
    <T> T call(ServiceDescriptor d, Class<T> returnType, Object[] args, CallContext context)
        throws TRADEException;
  }

  private final Registry registry;
  private final Access access;
  private final Calls calls;

  public AdminClient(Registry registry, Access access, Calls calls) {
    this.registry = registry;
    this.access = access;
    this.calls = calls;
  }

  /**
   * Calls the middleware service {@code name} of the container {@code containerId} as
   * {@code credentials}; a refusal there is thrown as its own typed error.
   */
  public <T> T call(String credentials, String containerId, String name, Class<T> returnType,
      Object... args) throws TRADEException {
    return call(credentials(credentials), system(containerId, name), returnType, args);
  }

  /**
   * Parses a credentials string of the API.
   *
   * @throws TRADEBadArgumentsException if it is not {@code <principal>:<secret>} (never showing
   *     the secret)
   */
  public static Credentials credentials(String text) throws TRADEBadArgumentsException {
    try {
      return Credentials.parse(text);
    } catch (IllegalArgumentException e) {
      throw new TRADEBadArgumentsException(e.getMessage());
    }
  }

  /** Calls {@code d} as {@code credentials}, whatever service it is. */
  public <T> T call(Credentials credentials, ServiceDescriptor d, Class<T> returnType,
      Object... args) throws TRADEException {
    try {
      return calls.call(d, returnType, args, access.context(credentials, d));
    } catch (TRADEInvocationException e) {
      // The operation failed in the container it was sent to: its own typed error is the answer.
      if (e.getCause() instanceof TRADEException) {
        throw (TRADEException) e.getCause();
      }
      throw e;
    }
  }

  /**
   * Each container this one knows, by name, with the names of the containers it links to, as each
   * says itself (its {@code neighbours} service, called as {@code credentials}). A container whose
   * middleware services are not known here is left out.
   */
  public Map<String, Collection<String>> graph(String credentials) throws TRADEException {
    Map<String, String> names = containerNames();
    Map<String, Collection<String>> graph = new TreeMap<>();
    for (Map.Entry<String, String> c : names.entrySet()) {
      List<?> ids = call(credentials, c.getKey(), "neighbours", List.class);
      List<String> linked = new ArrayList<>();
      for (Object id : ids) {
        linked.add(nameOf(names, id));
      }
      linked.sort(null);
      graph.put(c.getValue(), List.copyOf(linked));
    }
    return graph;
  }

  /**
   * The graph with each link's round-trip time: each container this one knows, by name, with the
   * microseconds to each container it links to whose time it has measured, by name, as each says
   * itself (its {@code roundTrips} service, called as {@code credentials}).
   */
  public Map<String, Map<String, Double>> roundTrips(String credentials) throws TRADEException {
    Map<String, String> names = containerNames();
    Map<String, Map<String, Double>> graph = new TreeMap<>();
    for (Map.Entry<String, String> c : names.entrySet()) {
      Map<?, ?> times = call(credentials, c.getKey(), "roundTrips", Map.class);
      Map<String, Double> linked = new TreeMap<>();
      times.forEach((id, micros) -> linked.put(nameOf(names, id), ((Number) micros).doubleValue()));
      graph.put(c.getValue(), Collections.unmodifiableMap(linked));
    }
    return graph;
  }

  private static String nameOf(Map<String, String> names, Object id) {
    return names.getOrDefault(String.valueOf(id), String.valueOf(id));
  }

  /** Every known container's {@code describeContainer()}, this one's first. */
  public List<Map<String, Object>> containers(String credentials) throws TRADEException {
    List<Map<String, Object>> result = new ArrayList<>();
    for (String id : containerNames().keySet()) {
      @SuppressWarnings("unchecked")
      Map<String, Object> m = call(credentials, id, "describeContainer", Map.class);
      result.add(m);
    }
    return result;
  }

  /** Container id → name of every container whose middleware services are known here. */
  private Map<String, String> containerNames() {
    Map<String, String> names = new LinkedHashMap<>();
    for (Entry e : registry.find("neighbours", SYSTEM)) {
      names.putIfAbsent(e.descriptor().containerId(), e.descriptor().containerName());
    }
    return names;
  }

  /**
   * The middleware service {@code name} of the container {@code containerId}.
   *
   * @throws TRADEServiceUnavailableException if that container, or the service, is not known here
   */
  public ServiceDescriptor system(String containerId, String name) throws TRADEException {
    for (Entry e : registry.find(name, SYSTEM)) {
      if (e.descriptor().containerId().equals(containerId)) {
        return e.descriptor();
      }
    }
    throw new TRADEServiceUnavailableException("Service not available: container " + containerId
        + " is not known here, or provides no " + name + " in group " + SystemGroup.NAME);
  }
}
