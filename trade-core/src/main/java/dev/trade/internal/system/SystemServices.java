package dev.trade.internal.system;

import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Finds and calls system services like any service: the clients behind the static API use it, so
 * that a feature's engine is reached only through a service call. Stateless and thread-safe.
 */
public final class SystemServices {
  private static final Query SYSTEM = new Query(null, null, null, Set.of(SystemGroup.NAME),
      Set.of(), false, null, null, Set.of(), List.of(), List.of());

  private static final Logger LOG = System.getLogger("dev.trade.registry");

  private SystemServices() {}

  /** System service {@code name} of every container that provides it, in preference order. */
  public static List<ServiceDescriptor> everywhere(Registry registry, String name) {
    List<ServiceDescriptor> result = new ArrayList<>();
    for (Entry e : registry.find(name, SYSTEM)) {
      result.add(e.descriptor());
    }
    return result;
  }

  /**
   * Calls system service {@code name} of container {@code containerId}. A request the service
   * refused with a {@code TRADEException} of its own reaches the caller as that exception.
   *
   * @throws TRADEServiceUnavailableException if that container is not known here, or provides
   *     no such service
   */
  public static <T> T call(Registry registry, ServiceCaller caller, String containerId,
      String name, Class<T> returnType, Object... args) throws TRADEException {
    ServiceDescriptor d = null;
    for (Entry e : registry.find(name, SYSTEM)) {
      if (e.descriptor().containerId().equals(containerId)) {
        d = e.descriptor();
        break;
      }
    }
    if (d == null) {
      throw new TRADEServiceUnavailableException("Service not available: container " + containerId
          + " is not known here, or provides no " + name + " in group " + SystemGroup.NAME);
    }
    return call(caller, d, returnType, args);
  }

  /**
   * Calls system service {@code name}, which returns a list of maps, in every container known
   * here, and joins the lists in preference order of the containers; a container that cannot be
   * reached is left out (logged at DEBUG).
   */
  public static List<Map<String, Object>> collect(Registry registry, ServiceCaller caller,
      String name) {
    List<Map<String, Object>> all = new ArrayList<>();
    for (ServiceDescriptor d : everywhere(registry, name)) {
      try {
        for (Object m : call(caller, d, List.class)) {
          @SuppressWarnings("unchecked")
          Map<String, Object> one = (Map<String, Object>) m;
          all.add(one);
        }
      } catch (TRADEException e) {
        LOG.log(Level.DEBUG, "{0} of container {1} failed: {2}", name, d.containerName(),
            e.getMessage());
      }
    }
    return all;
  }

  /** Calls system service {@code d}, unwrapping its own refusal as {@link #call} does. */
  public static <T> T call(ServiceCaller caller, ServiceDescriptor d, Class<T> returnType,
      Object... args) throws TRADEException {
    try {
      return caller.call(d, returnType, args, 0);
    } catch (TRADEInvocationException e) {
      // The request was refused in the container it was sent to: its own typed error is the answer.
      if (e.getCause() instanceof TRADEException) {
        throw (TRADEException) e.getCause();
      }
      throw e;
    }
  }
}
