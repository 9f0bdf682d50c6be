package dev.trade.internal.call;

import dev.trade.TRADEException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;

/**
 * What a {@code TRADEServiceInfo} calls through: the container it was obtained from (or decoded
 * in). Implementations are thread-safe.
 */
public interface ServiceCaller {
  /** Id of this container's incarnation, to tell local services from remote ones. */
  String containerId();

  /**
   * How many links separate this container from the service's (0: this one), or -1 when the
   * service is not known here (any more).
   */
  int distance(ServiceDescriptor service);

  /**
   * Calls the service and returns its result as {@code returnType}.
   *
   * @param timeoutNanos how long to wait for a remote reply; non-positive means the default
   */
  <T> T call(ServiceDescriptor service, Class<T> returnType, Object[] args, long timeoutNanos)
      throws TRADEException;

  /**
   * Calls the service under lock {@code lock} (null: none), waiting for the service while another
   * lock holds it when {@code waitForLock}; otherwise as {@link #call}.
   */
  default <T> T callUnderLock(ServiceDescriptor service, UUID lock, boolean waitForLock,
      Class<T> returnType, Object[] args, long timeoutNanos) throws TRADEException {
    if (lock != null || waitForLock) {
      throw new UnsupportedOperationException("this caller does not take calls under locks");
    }
    return call(service, returnType, args, timeoutNanos);
  }

  /**
   * Calls the service without waiting; the future fails with the {@code TRADEException} that
   * {@link #call} would throw. A remote call holds no thread while its reply is outstanding.
   */
  <T> CompletableFuture<T> callAsync(ServiceDescriptor service, Class<T> returnType, Object[] args,
      long timeoutNanos);
}
