package dev.trade.internal.registry;

import java.lang.annotation.Annotation;
import java.util.ArrayList;
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
 * @param genericReturnTypeName {@link java.lang.reflect.Type#getTypeName()} of the generic return
 *     type ({@code java.util.Set<com.acme.Symbol>}); equal to {@code returnTypeName} when it is not
 *     generic
 * @param exceptionTypeNames {@link Class#getName()} of each exception type the method declares
 * @param parameterAnnotations the annotations of each parameter (those whose class is known here),
 *     one list per parameter
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
    List<Annotation> annotations,
    String genericReturnTypeName,
    List<String> exceptionTypeNames,
    List<List<Annotation>> parameterAnnotations) {

  /** A descriptor with no generic return type, no declared exceptions and no parameter annotations. */
  public ServiceDescriptor(String containerId, String containerName, String host, long serviceId,
      String name, List<String> parameterNames, List<String> parameterTypeNames,
      String returnTypeName, Set<String> groups, List<Annotation> annotations) {
    this(containerId, containerName, host, serviceId, name, parameterNames, parameterTypeNames,
        returnTypeName, groups, annotations, returnTypeName, List.of(),
        Collections.nCopies(parameterNames.size(), List.of()));
  }

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
    Objects.requireNonNull(genericReturnTypeName, "genericReturnTypeName == null");
    exceptionTypeNames = List.copyOf(exceptionTypeNames);
    List<List<Annotation>> perParameter = new ArrayList<>(parameterAnnotations.size());
    for (List<Annotation> list : parameterAnnotations) {
      perParameter.add(List.copyOf(list));
    }
    parameterAnnotations = List.copyOf(perParameter);
    if (parameterNames.size() != parameterTypeNames.size()
        || parameterNames.size() != parameterAnnotations.size()) {
      throw new IllegalArgumentException("parameterNames, parameterTypeNames and"
          + " parameterAnnotations differ in length for " + name);
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
