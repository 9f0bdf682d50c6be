package dev.trade.internal.registry;

import java.lang.annotation.Annotation;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * Everything known about one provided service, independent of who holds it: the immutable data
 * behind a {@code TRADEServiceInfo}, as it is replicated to every container and as it travels.
 *
 * <p>A service is identified by {@code (containerId, serviceId)}: the container id is unique per
 * container incarnation and service ids are never reused within a container.
 *
 * @param containerId unique id of the providing container's incarnation
 * @param containerName the providing container's human-readable name
 * @param host the providing container's host name or address, as it announced itself
 * @param serviceId per-container service number, never reused
 * @param name the method name
 * @param parameterNames the parameter names (real names when compiled with {@code -parameters})
 * @param parameterTypeNames {@link Class#getTypeName()} of each parameter type
 * @param returnTypeName {@link Class#getTypeName()} of the return type
 * @param groups the groups the service was registered in, in registration order (may be empty)
 * @param annotations the annotations on the service method (those whose class is known here)
 */
public record ServiceDescriptor(
    String containerId,
    String containerName,
    String host,
    long serviceId,
    String name,
    List<String> parameterNames,
    List<String> parameterTypeNames,
    String returnTypeName,
    Set<String> groups,
    List<Annotation> annotations) {

  public ServiceDescriptor {
    Objects.requireNonNull(containerId, "containerId == null");
    Objects.requireNonNull(containerName, "containerName == null");
    Objects.requireNonNull(host, "host == null");
    Objects.requireNonNull(name, "name == null");
    parameterNames = List.copyOf(parameterNames);
    parameterTypeNames = List.copyOf(parameterTypeNames);
    Objects.requireNonNull(returnTypeName, "returnTypeName == null");
    groups = Collections.unmodifiableSet(new LinkedHashSet<>(groups)); // keeps the given order
    annotations = List.copyOf(annotations);
    if (parameterNames.size() != parameterTypeNames.size()) {
      throw new IllegalArgumentException(
          "parameterNames and parameterTypeNames differ in length for " + name);
    }
  }

  /** {@code name(T1,T2)}, with each parameter's type name: the TRADE {@code serviceString}. */
  public String signature() {
    return name + "(" + String.join(",", parameterTypeNames) + ")";
  }

  /** True when both describe the same provided service (same container incarnation and id). */
  public boolean sameService(ServiceDescriptor other) {
    return serviceId == other.serviceId && containerId.equals(other.containerId);
  }
}
