package dev.trade.internal.registry;

import java.lang.invoke.MethodHandle;
import java.lang.reflect.Method;
import java.util.List;
import java.util.Set;

/**
 * A service provided by this container: its descriptor, the provider object and a method handle
 * prepared once at registration. Immutable apart from the {@code active} flag, which goes false
 * exactly once, when the service is deregistered. Thread-safe.
 */
public final class LocalService {
  private final ServiceDescriptor descriptor;
  private final Object target;
  private final Method method;
  private final List<Class<?>> parameterTypes;
  private final MethodHandle invoker;
  private final Set<String> declaredTypes;
  private volatile boolean active = true;

  LocalService(ServiceDescriptor descriptor, Object target, Method method, MethodHandle invoker) {
    this.descriptor = descriptor;
    this.target = target;
    this.method = method;
    this.parameterTypes = List.of(method.getParameterTypes());
    this.invoker = invoker;
    this.declaredTypes = DeclaredTypes.of(method);
  }

  /**
   * This service with another descriptor (its groups changed): same provider, method and handle,
   * active; this one stays as it is for the calls that hold it.
   */
  LocalService withDescriptor(ServiceDescriptor changed) {
    return new LocalService(changed, target, method, invoker);
  }

  public ServiceDescriptor descriptor() {
    return descriptor;
  }

  /** The provider object the service was registered with. */
  public Object target() {
    return target;
  }

  public Method method() {
    return method;
  }

  public List<Class<?>> parameterTypes() {
    return parameterTypes;
  }

  public Class<?> returnType() {
    return method.getReturnType();
  }

  /**
   * The binary names of the classes the method's signature declares ({@link DeclaredTypes}):
   * decodable in its calls and replies whatever the allow-list says.
   */
  public Set<String> declaredTypes() {
    return declaredTypes;
  }

  /** Typed {@code (Object target, Object[] args) Object}; void methods return null. */
  public MethodHandle invoker() {
    return invoker;
  }

  public boolean isActive() {
    return active;
  }

  void deactivate() {
    active = false;
  }
}
