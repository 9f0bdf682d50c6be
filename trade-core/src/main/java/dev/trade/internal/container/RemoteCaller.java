package dev.trade.internal.container;

import dev.trade.TRADEException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.Returns;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.net.Network;
import dev.trade.internal.registry.DeclaredTypes;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Types;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.function.Supplier;

/**
 * The caller half's remote way: what a call to another container needs before the network encodes,
 * sends and waits for it (the caller's class loader, the declared return type as it sees it, the
 * allow-list entries of the types the caller's own code names). Safe for concurrent use.
 */
final class RemoteCaller {
  private static final int MAX_RESOLVED = 1024;

  private record Resolved(ClassLoader loader, Class<?> type) {}

  private record Declared(ClassLoader loader, Set<String> names) {}

  private final AllowList allowList;
  private final Supplier<Network> network;
  /** Declared return types of services called from here, by type name; see declaredReturnType. */
  private final Map<String, Resolved> returnTypes = new ConcurrentHashMap<>();
  /** What remote services' signatures declare, by generic return and exception type names. */
  private final Map<String, Declared> declaredTypes = new ConcurrentHashMap<>();

  /** @param network this container's networking, or null when it has none */
  RemoteCaller(AllowList allowList, Supplier<Network> network) {
    this.allowList = allowList;
    this.network = network;
  }

  /** Calls {@code d} in another container with arguments already normalized and counted. */
  <T> T call(ServiceDescriptor d, Class<T> returnType, Object[] args, CallContext context,
      long timeoutNanos) throws TRADEException {
    long deadline = System.nanoTime() + timeoutNanos;
    Network n = network(d);
    ClassLoader loader = prepare(d, returnType);
    return Returns.convert(d, returnType,
        n.call(d, args, context, deadline, loader, declaredTypes(d, loader)));
  }

  /**
   * As {@link #call}, without waiting: the future completes with the converted result (decoded on
   * {@code executor}) or fails with the {@code TRADEException} that {@link #call} would throw. No
   * thread waits while the reply is outstanding.
   */
  <T> CompletableFuture<T> callAsync(ServiceDescriptor d, Class<T> returnType, Object[] args,
      CallContext context, long timeoutNanos, Executor executor) throws TRADEException {
    long deadline = System.nanoTime() + timeoutNanos;
    Network n = network(d);
    ClassLoader loader = prepare(d, returnType);
    return n.callAsync(d, args, context, deadline, loader, declaredTypes(d, loader), executor)
        .thenApply(v -> {
          try {
            return Returns.convert(d, returnType, v);
          } catch (TRADEException e) {
            throw new CompletionException(e);
          }
        });
  }

  private Network network(ServiceDescriptor d) throws TRADEException {
    Network n = network.get();
    if (n == null) {
      throw CallErrors.gone(d, "this container has no network");
    }
    return n;
  }

  /**
   * Checks the requested return type against the declared one and lets the types the caller's own
   * code names arrive; returns the loader the reply is decoded in.
   */
  private ClassLoader prepare(ServiceDescriptor d, Class<?> returnType) throws TRADEException {
    ClassLoader loader = callerLoader(returnType);
    Class<?> declared = declaredReturnType(d, loader);
    Returns.check(d, returnType, declared);
    // The types the caller's own code names may arrive: the declared return type when this JVM
    // has it, and the requested one. Nothing a remote peer names alone is allowed this way.
    if (declared != null) {
      allowList.addPackageOf(declared);
    }
    allowList.addPackageOf(returnType);
    return loader;
  }

  /**
   * The classes the service's return and exception types declare, as far as {@code loader} knows
   * them ({@link DeclaredTypes}): its replies may hold them without the allow-list naming them.
   */
  private Set<String> declaredTypes(ServiceDescriptor d, ClassLoader loader) {
    // Walking the classes on every call would cost more than the call's own preparation.
    String key = d.genericReturnTypeName() + " throws " + d.exceptionTypeNames();
    Declared known = declaredTypes.get(key);
    if (known != null && known.loader == loader) {
      return known.names;
    }
    Set<String> names = DeclaredTypes.of(d.genericReturnTypeName(), d.exceptionTypeNames(), loader);
    if (declaredTypes.size() >= MAX_RESOLVED) {
      declaredTypes.clear(); // names come from peers' tables: bounded, not trusted
    }
    declaredTypes.put(key, new Declared(loader, names));
    return names;
  }

  /** The service's declared return type as {@code loader} sees it, or null if it cannot. */
  private Class<?> declaredReturnType(ServiceDescriptor d, ClassLoader loader) {
    // Class.forName on every call would cost more than the rest of a call's preparation.
    Resolved r = returnTypes.get(d.returnTypeName());
    if (r != null && r.loader == loader) {
      return r.type;
    }
    Class<?> type = Types.resolve(d.returnTypeName(), loader);
    if (returnTypes.size() >= MAX_RESOLVED) {
      returnTypes.clear(); // names come from peers' tables: bounded, not trusted
    }
    returnTypes.put(d.returnTypeName(), new Resolved(loader, type));
    return type;
  }

  /** The class loader of the calling code: the thread's context loader, else the type's. */
  static ClassLoader callerLoader(Class<?> returnType) {
    ClassLoader l = Thread.currentThread().getContextClassLoader();
    if (l == null) {
      l = returnType.getClassLoader();
    }
    return l != null ? l : RemoteCaller.class.getClassLoader();
  }
}
