package dev.trade.internal.registry;

import java.util.Objects;

/**
 * One service as this container knows it: its descriptor, how far away its container is (0 for
 * this container, otherwise the number of links a call crosses) and, for services of this
 * container, the {@link LocalService} that runs it. Immutable; the resolved-type cache is benign
 * racy (any thread may fill it, all fill it with the same classes). Thread-safe.
 */
public final class Entry {
  private final ServiceDescriptor descriptor;
  private final int distance;
  private final LocalService local;
  private volatile Class<?>[] resolvedParameters;
  private volatile Class<?> resolvedReturn;

  Entry(ServiceDescriptor descriptor, int distance, LocalService local) {
    this.descriptor = Objects.requireNonNull(descriptor, "descriptor == null");
    this.distance = distance;
    this.local = local;
    if (local != null) {
      resolvedParameters = local.parameterTypes().toArray(new Class<?>[0]);
      resolvedReturn = local.returnType();
    }
  }

  public ServiceDescriptor descriptor() {
    return descriptor;
  }

  public int distance() {
    return distance;
  }

  /** The local service, or null when the service lives in another container. */
  public LocalService local() {
    return local;
  }

  Entry withDistance(int newDistance) {
    return newDistance == distance ? this : new Entry(descriptor, newDistance, local);
  }

  /**
   * The declared type of parameter {@code i}, resolved with {@code hint}, this thread's context
   * loader or TRADE's own loader, or null when none of them knows it.
   */
  public Class<?> parameterType(int i, ClassLoader hint) {
    Class<?>[] resolved = resolvedParameters;
    if (resolved == null) {
      resolved = new Class<?>[descriptor.parameterTypeNames().size()];
      resolvedParameters = resolved;
    }
    Class<?> c = resolved[i];
    if (c == null) {
      c = resolve(descriptor.parameterTypeNames().get(i), hint);
      resolved[i] = c;
    }
    return c;
  }

  /** The declared return type, resolved like {@link #parameterType}, or null when unknown. */
  public Class<?> returnType(ClassLoader hint) {
    Class<?> c = resolvedReturn;
    if (c == null) {
      c = resolve(descriptor.returnTypeName(), hint);
      resolvedReturn = c;
    }
    return c;
  }

  private static Class<?> resolve(String name, ClassLoader hint) {
    Class<?> c = hint == null ? null : Types.resolve(name, hint);
    if (c == null) {
      ClassLoader context = Thread.currentThread().getContextClassLoader();
      c = context == null ? null : Types.resolve(name, context);
    }
    return c != null ? c : Types.resolve(name, Entry.class.getClassLoader());
  }

  @Override
  public String toString() {
    return descriptor.signature() + "@" + descriptor.containerName() + " (distance " + distance + ")";
  }
}
