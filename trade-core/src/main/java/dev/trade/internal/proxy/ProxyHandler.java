package dev.trade.internal.proxy;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Method;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Supplier;

/**
 * One proxy's calls: each method's service is found on its first call and kept while the
 * container still knows it; once it is gone (deregistered, its container left) or a call found it
 * unavailable, the next call finds one again. Safe for concurrent use.
 */
final class ProxyHandler implements InvocationHandler {
  /** One method's model and the service it currently calls. */
  private static final class Slot {
    final MethodModel model;
    // Racing callers may both look up; either result is a valid binding.
    volatile TRADEServiceInfo info;
    /** The generation in which {@link #info} was last known to exist. */
    volatile Object seen;

    Slot(MethodModel model) {
      this.model = model;
    }
  }

  private final Class<?> type;
  private final Map<Method, Slot> slots;
  private final Proxies.Services services;
  private final TRADEServiceConstraints constraints;
  private final String constraintsText;
  private final Supplier<Executor> executor;

  ProxyHandler(Class<?> type, Map<Method, MethodModel> models, Proxies.Services services,
      TRADEServiceConstraints constraints, Supplier<Executor> executor) {
    this.type = type;
    Map<Method, Slot> s = new HashMap<>();
    models.forEach((m, model) -> s.put(m, new Slot(model)));
    this.slots = s;
    this.services = services;
    this.constraints = constraints;
    this.constraintsText = constraints == null ? "" : " " + constraints;
    this.executor = executor;
  }

  @Override
  public Object invoke(Object proxy, Method method, Object[] args) throws Throwable {
    Slot slot = slots.get(method);
    if (slot == null) {
      return local(proxy, method, args);
    }
    MethodModel model = slot.model;
    if (!model.async) {
      try {
        return call(slot, args);
      } catch (TRADEException e) {
        throw model.failure(e);
      }
    }
    CompletableFuture<Object> result = new CompletableFuture<>();
    try {
      executor.get().execute(() -> {
        try {
          result.complete(call(slot, args));
        } catch (TRADEException e) {
          result.completeExceptionally(model.failure(e));
        } catch (RuntimeException | Error e) {
          result.completeExceptionally(e);
        }
      });
    } catch (RejectedExecutionException e) {
      result.completeExceptionally(new IllegalStateException("the container is closed", e));
    }
    return result;
  }

  private Object call(Slot slot, Object[] args) throws TRADEException {
    TRADEServiceInfo info = slot.info;
    Object generation = services.generation();
    if (info == null || slot.seen != generation && info.getDistance() < 0) {
      info = services.find(constraints, slot.model.name, slot.model.parameterTypes);
      slot.info = info;
    }
    slot.seen = generation;
    try {
      return info.call(slot.model.callType, args);
    } catch (TRADEServiceUnavailableException e) {
      slot.info = null; // gone while we called: find it again next time
      throw e;
    }
  }

  private Object local(Object proxy, Method method, Object[] args) throws Throwable {
    if (method.isDefault()) {
      return InvocationHandler.invokeDefault(proxy, method, args);
    }
    switch (method.getName()) {
      case "equals":
        return proxy == args[0];
      case "hashCode":
        return System.identityHashCode(proxy);
      case "toString":
        return "TRADE proxy for " + type.getName() + constraintsText;
      default:
        throw new UnsupportedOperationException(MethodModel.describe(method));
    }
  }
}
