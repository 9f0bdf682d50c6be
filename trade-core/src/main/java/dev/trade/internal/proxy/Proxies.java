package dev.trade.internal.proxy;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.util.Map;
import java.util.Objects;

/**
 * Makes the typed proxies of one container. Safe for concurrent use.
 */
public final class Proxies implements AutoCloseable {
  // Parsed once per interface for the life of the class (Retrofit's per-method cache); a
  // ClassValue does not keep the interface's class loader alive.
  private static final ClassValue<Map<Method, MethodModel>> MODELS = new ClassValue<>() {
    @Override
    protected Map<Method, MethodModel> computeValue(Class<?> type) {
      return MethodModel.parse(type);
    }
  };

  /** What proxies find and call services through: their container. */
  public interface Services {
    /**
     * The preferred service named {@code name} whose parameters take {@code parameterTypes}, among
     * those matching {@code constraints}.
     */
    TRADEServiceInfo find(TRADEServiceConstraints constraints, String name, Class<?>[] parameterTypes)
        throws TRADEException;

    /**
     * An object replaced whenever the set of known services changes: while it is the same
     * (by identity), a service found earlier is still known.
     */
    Object generation();
  }

  private final Services services;
  private final String containerName;
  private volatile boolean closed;

  public Proxies(Services services, String containerName) {
    this.services = Objects.requireNonNull(services, "services == null");
    this.containerName = containerName;
  }

  /**
   * A proxy implementing {@code type}.
   *
   * @param constraints narrows every method's lookup; null for none. Kept as given: pass a copy
   *     that no one changes later
   * @throws IllegalArgumentException if {@code type} is not an interface or one of its methods
   *     cannot be a service call (the message names the method and the fix)
   */
  public <T> T create(Class<T> type, TRADEServiceConstraints constraints) {
    Objects.requireNonNull(type, "type == null");
    Map<Method, MethodModel> models = MODELS.get(type);
    ProxyHandler handler = new ProxyHandler(type, models, services, constraints, this::closedError);
    return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, handler));
  }

  /** Why an asynchronous call cannot be sent: null while the container is open. */
  private IllegalStateException closedError() {
    return closed ? new IllegalStateException("container " + containerName + " is closed") : null;
  }

  /** Makes later asynchronous calls fail at once; calls already sent still complete. Idempotent. */
  @Override
  public void close() {
    closed = true;
  }
}
