package dev.trade.internal.call;

import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;

/**
 * The terminal link on the providing side: checks the arguments against the signature and invokes
 * the prepared method handle. Whatever the service throws reaches the caller as the cause of a
 * {@link TRADEInvocationException}; errors of the JVM itself ({@link VirtualMachineError}) are not
 * wrapped. Thread-safe.
 */
public final class LocalInvoker implements CallLink {
  private final Registry registry;

  public LocalInvoker(Registry registry) {
    this.registry = registry;
  }

  @Override
  public Object proceed(Invocation call, Next next) throws TRADEException {
    ServiceDescriptor d = call.service();
    LocalService s = registry.local(d.serviceId());
    if (s == null || !s.isActive() || !s.descriptor().containerId().equals(d.containerId())) {
      throw CallErrors.gone(d, "it was deregistered");
    }
    Object[] args = Arguments.check(d, s.parameterTypes(), call.args());
    try {
      return (Object) s.invoker().invokeExact(s.target(), args);
    } catch (VirtualMachineError e) {
      throw e;
    } catch (Throwable t) {
      throw CallErrors.threw(d, t);
    }
  }

}
