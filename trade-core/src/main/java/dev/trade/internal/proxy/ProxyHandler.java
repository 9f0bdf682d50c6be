package dev.trade.internal.proxy;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Method;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
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
  /**
   * The slots by the {@code Method} objects the proxy class passes, compared by identity: the
   * proxy's {@code Method}s are copies of those {@link #slots} was made with, and
   * {@code Method.equals} compares their parameter types one by one. Copy-on-write.
   */
  private volatile Map<Method, Slot> byIdentity = new IdentityHashMap<>();
  private final Proxies.Services services;
  private final TRADEServiceConstraints constraints;
  private final String constraintsText;
  private final Supplier<IllegalStateException> closedError;

  ProxyHandler(Class<?> type, Map<Method, MethodModel> models, Proxies.Services services,
      TRADEServiceConstraints constraints, Supplier<IllegalStateException> closedError) {
    this.type = type;
    Map<Method, Slot> s = new HashMap<>();
    models.forEach((m, model) -> s.put(m, new Slot(model)));
    this.slots = s;
    this.services = services;
    this.constraints = constraints;
    this.constraintsText = constraints == null ? "" : " " + constraints;
    this.closedError = closedError;
  }

  /**
   * Adds {@code method} to {@link #byIdentity}. The proxy class passes the same {@code Method}
   * object for a method on every call, so this happens once per method; the bound only guards
   * against callers of this handler that pass copies.
   */
  private synchronized void remember(Method method, Slot slot) {
    if (byIdentity.size() < 2 * slots.size()) {
      Map<Method, Slot> copy = new IdentityHashMap<>(byIdentity);
      copy.put(method, slot);
      byIdentity = copy;
    }
  }

  @Override
  public Object invoke(Object proxy, Method method, Object[] args) throws Throwable {
    Slot slot = byIdentity.get(method);
    if (slot == null) {
      slot = slots.get(method);
      if (slot == null) {
        return local(proxy, method, args);
      }
      remember(method, slot);
    }
    MethodModel model = slot.model;
    if (!model.async) {
      try {
        return call(slot, args);
      } catch (TRADEException e) {
        throw model.failure(e);
      }
    }
    IllegalStateException closed = closedError.get();
    if (closed != null) {
      return CompletableFuture.failedFuture(closed);
    }
    return callAsync(slot, args);
  }

  /**
   * The asynchronous call: found on the caller's thread (a lookup in the container's own table),
   * then sent without a thread waiting for the reply.
   */
  private CompletableFuture<Object> callAsync(Slot slot, Object[] args) {
    MethodModel model = slot.model;
    TRADEServiceInfo info;
    try {
      info = bound(slot);
    } catch (TRADEException e) {
      return CompletableFuture.failedFuture(model.failure(e));
    }
    CompletableFuture<?> call;
    try {
      call = info.callAsync(model.callType, args);
    } catch (RuntimeException e) { // the container closed while we looked
      return CompletableFuture.failedFuture(e);
    }
    CompletableFuture<Object> result = new CompletableFuture<>();
    call.whenComplete((value, failure) -> {
      if (failure == null) {
        result.complete(value);
        return;
      }
      Throwable cause = failure instanceof CompletionException && failure.getCause() != null
          ? failure.getCause() : failure;
      if (cause instanceof TRADEException) {
        unbindIfGone(slot, (TRADEException) cause);
        result.completeExceptionally(model.failure((TRADEException) cause));
      } else {
        result.completeExceptionally(cause);
      }
    });
    return result;
  }

  private Object call(Slot slot, Object[] args) throws TRADEException {
    TRADEServiceInfo info = bound(slot);
    try {
      return info.call(slot.model.callType, args);
    } catch (TRADEException e) {
      unbindIfGone(slot, e);
      throw e;
    }
  }

  /** The service {@code slot}'s method calls now: the one found before while it is known. */
  private TRADEServiceInfo bound(Slot slot) throws TRADEException {
    TRADEServiceInfo info = slot.info;
    Object generation = services.generation();
    if (info == null || slot.seen != generation && info.getDistance() < 0) {
      info = services.find(constraints, slot.model.name, slot.model.parameterTypes);
      slot.info = info;
    }
    if (slot.seen != generation) { // a volatile write on every call would cost more than a read
      slot.seen = generation;
    }
    return info;
  }

  private static void unbindIfGone(Slot slot, TRADEException e) {
    if (e instanceof TRADEServiceUnavailableException) {
      slot.info = null; // gone while we called: find it again next time
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
