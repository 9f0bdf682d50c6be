package dev.trade.internal.proxy;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Makes the typed proxies of one container, and owns the threads their asynchronous methods run
 * on. Safe for concurrent use.
 */
public final class Proxies implements AutoCloseable {
  /**
   * The most asynchronous proxy calls in progress at once; later ones queue. Each holds a thread
   * for the whole call, because calls block; a bound keeps a burst of them from growing threads
   * without limit.
   */
  static final int ASYNC_THREADS = 16;

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
  private final Object lock = new Object();
  // Guarded by lock; made on the first asynchronous call.
  private ExecutorService async;
  private boolean closed;

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
    ProxyHandler handler = new ProxyHandler(type, models, services, constraints, this::executor);
    return type.cast(Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type}, handler));
  }

  private Executor executor() {
    synchronized (lock) {
      if (closed) {
        throw new IllegalStateException("container " + containerName + " is closed");
      }
      if (async == null) {
        AtomicInteger n = new AtomicInteger();
        ThreadPoolExecutor pool = new ThreadPoolExecutor(ASYNC_THREADS, ASYNC_THREADS, 30,
            TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
              Thread t = new Thread(r, "trade-proxy-" + containerName + "-" + n.incrementAndGet());
              t.setDaemon(true);
              return t;
            });
        pool.allowCoreThreadTimeOut(true);
        async = pool;
      }
      return async;
    }
  }

  /** Stops the asynchronous calls' threads; calls already queued still run. Idempotent. */
  @Override
  public void close() {
    synchronized (lock) {
      closed = true;
      if (async != null) {
        async.shutdown();
      }
    }
  }
}
