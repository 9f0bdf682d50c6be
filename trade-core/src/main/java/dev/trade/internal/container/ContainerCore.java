package dev.trade.internal.container;

import dev.trade.TRADEException;
import dev.trade.internal.call.Arguments;
import dev.trade.internal.call.CallChain;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.LocalInvoker;
import dev.trade.internal.call.Returns;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.call.ValueCopier;
import dev.trade.internal.config.Settings;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The machinery behind one {@code TRADEContainer}: identity, registry and the call chain.
 *
 * <p>A call takes one path: {@code route → (local: [copy] → host chain → [copy] | remote)}, where
 * the host chain ({@code hooks → locks → invoke}) runs in the container that provides the service,
 * so that it sees calls from everywhere. This class is safe for concurrent use.
 */
public final class ContainerCore implements ServiceCaller {
  private static final AtomicInteger INSTANCES = new AtomicInteger();

  private final String id = UUID.randomUUID().toString();
  private final String name;
  private final String host;
  private final Settings settings;
  private final Registry registry;
  private final CallChain hostChain;
  private final ValueCopier copier;
  private final long defaultTimeoutNanos;
  private volatile boolean closed;

  /**
   * @param copier copies arguments and results of local calls (strict mode), or null to pass
   *     them as they are
   */
  public ContainerCore(Settings settings, ValueCopier copier) {
    this.settings = settings;
    this.host = HostName.local();
    int n = INSTANCES.incrementAndGet();
    String configured = settings.containerName();
    this.name = configured.isEmpty()
        ? host + "/" + ProcessHandle.current().pid() + (n == 1 ? "" : "#" + n)
        : configured;
    this.registry = new Registry(id, name, host);
    this.copier = settings.copyDataForLocalInvokes() ? copier : null;
    this.defaultTimeoutNanos = settings.callTimeout().toNanos();
    List<CallLink> hostLinks = new ArrayList<>();
    this.hostChain = new CallChain(hostLinks, new LocalInvoker(registry));
  }

  @Override
  public String containerId() {
    return id;
  }

  public String name() {
    return name;
  }

  public String host() {
    return host;
  }

  public Settings settings() {
    return settings;
  }

  public Registry registry() {
    return registry;
  }

  public boolean isClosed() {
    return closed;
  }

  @Override
  public <T> T call(ServiceDescriptor d, Class<T> returnType, Object[] args, long timeoutNanos)
      throws TRADEException {
    Object[] normalized = Arguments.normalize(d, args);
    long deadline = System.nanoTime() + (timeoutNanos > 0 ? timeoutNanos : defaultTimeoutNanos);
    if (d.containerId().equals(id)) {
      return callLocal(d, returnType, normalized, deadline);
    }
    throw LocalInvoker.unavailable(d, "its container is not connected");
  }

  private <T> T callLocal(ServiceDescriptor d, Class<T> returnType, Object[] args, long deadline)
      throws TRADEException {
    LocalService s = registry.local(d.serviceId());
    if (s == null) {
      throw LocalInvoker.unavailable(d, "it was deregistered");
    }
    Returns.check(d, returnType, s.returnType());
    if (copier == null) {
      return Returns.convert(d, returnType, hostChain.call(new Invocation(d, args, deadline)));
    }
    ClassLoader providerLoader = s.target().getClass().getClassLoader();
    Object[] copies = new Object[args.length];
    for (int i = 0; i < args.length; i++) {
      copies[i] = copier.copy(args[i], providerLoader);
    }
    Object result = hostChain.call(new Invocation(d, copies, deadline));
    ClassLoader callerLoader = Thread.currentThread().getContextClassLoader();
    return Returns.convert(d, returnType,
        copier.copy(result, callerLoader != null ? callerLoader : providerLoader));
  }

  /** Deregisters everything and stops; idempotent. */
  public void close() {
    if (!closed) {
      closed = true;
      registry.deregisterAll();
    }
  }
}
