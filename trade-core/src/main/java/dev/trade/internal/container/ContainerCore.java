package dev.trade.internal.container;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceNotFoundException;
import dev.trade.internal.call.Arguments;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.CallChain;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.Caller;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.LocalInvoker;
import dev.trade.internal.call.Provider;
import dev.trade.internal.call.Returns;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.call.ValueCopier;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.config.Settings;
import dev.trade.internal.lock.Locks;
import dev.trade.internal.hooks.HookClient;
import dev.trade.internal.hooks.HookPath;
import dev.trade.internal.hooks.Hooks;
import dev.trade.internal.net.Network;
import dev.trade.internal.notify.NotificationClient;
import dev.trade.internal.notify.NotificationService;
import dev.trade.internal.notify.Notifications;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import dev.trade.internal.admin.Access;
import dev.trade.internal.admin.AdminClient;
import dev.trade.internal.admin.AdminService;
import dev.trade.internal.time.Scheduler;
import dev.trade.internal.system.SystemServices;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Function;

/**
 * The machinery behind one {@code TRADEContainer}: identity, registry and the call chain.
 *
 * <p>A call takes one path: {@code route → (local: [copy] → host chain → [copy] | remote)}, where
 * the host chain ({@link #hostLinks}) runs in the container that provides the service, so that it
 * sees calls from everywhere.
 *
 * <p>At start it registers its system providers (the notification and hook services) in the reserved group
 * {@link SystemGroup#NAME}, before networking starts, so that the first table it replicates holds
 * them. This class is safe for concurrent use.
 */
public final class ContainerCore implements ServiceCaller {
  private static final Logger LOG = System.getLogger("dev.trade.registry");
  private static final AtomicInteger INSTANCES = new AtomicInteger();
  private final UUID uuid = UUID.randomUUID();
  private final String id = uuid.toString();
  private final String name;
  private final String host;
  private final Settings settings;
  private final Registry registry;
  private final CallChain hostChain;
  /** The host chain without the hooks link, for calls no hook concerns ({@link #host}). */
  private final CallChain bareChain;
  private final RemoteCaller remote;
  /** This container as the caller of its own local calls. */
  private final Caller self;
  private final AllowList allowList;
  private final Codec codec;
  private final ValueCopier copier;
  private final long defaultTimeoutNanos;
  private final Limits limits;
  /** The one clock and timer of this container, handed to networking and notifications. */
  private final Scheduler scheduler;
  // Written once under this' lock; networking may start later, when discovery is switched on.
  private volatile Network network;
  private volatile boolean closed;
  private final Notifications notifications;
  private final NotificationClient notificationClient;
  private final Locks locks;
  private final Access access;
  private final AdminClient adminClient;
  /** The container's own providers (in the reserved group), which reset() leaves alone. */
  private final Set<Object> systemProviders =
      Collections.synchronizedSet(Collections.newSetFromMap(new IdentityHashMap<>()));
  private final Hooks hooks;
  /** Runs local asynchronous calls and decodes remote replies of asynchronous calls; lazily made. */
  private ExecutorService asyncPool; // Guarded by this.

  /**
   * Builds the container and, when the settings ask for networking, starts it.
   *
   * @param infos how {@code TRADEServiceInfo} values are described and bound to this container
   * @param constraints turns a {@code TRADEServiceConstraints} into a query; null for anything else
   * @throws UncheckedIOException if a listen address cannot be bound (the message names it)
   */
  public ContainerCore(Settings settings, InfoBinding infos, Function<Object, Query> constraints) {
    this.settings = settings;
    this.host = HostName.local();
    int n = INSTANCES.incrementAndGet();
    String configured = settings.containerName();
    this.name = configured.isEmpty()
        ? host + "/" + ProcessHandle.current().pid() + (n == 1 ? "" : "#" + n)
        : configured;
    this.registry = new Registry(id, name, host);
    this.allowList = AllowList.withDefaults();
    for (String pattern : settings.serializationAllowList()) {
      allowList.add(pattern);
    }
    this.limits = new Limits(settings.maxFrameSize(), Limits.DEFAULT.maxDepth(),
        Limits.DEFAULT.maxElements(), Limits.DEFAULT.maxStackFrames());
    this.codec = new Codec(allowList, limits, infos);
    this.copier = settings.copyDataForLocalInvokes() ? codec::copy : null;
    this.defaultTimeoutNanos = settings.callTimeout().toNanos();
    this.access = Access.of(settings, id, name, registry);
    this.locks = new Locks(registry, this, infos, settings.failureTimeout(), settings.callTimeout(),
        name);
    this.hooks = new Hooks(registry, this, infos, constraints, settings.hookTimeout(),
        settings.hookSystemServices(), settings.callLogMaxBytes(), name);
    LocalInvoker invoker = new LocalInvoker(registry);
    this.hostChain = new CallChain(hostLinks(access.link(), locks.link(), hooks.link()), invoker);
    // The same chain without the hooks link, for the calls no hook concerns (see the host chain's
    // entry below): a link passed through costs about 20 ns a local call.
    this.bareChain = new CallChain(hostLinks(access.link(), locks.link(), null), invoker);
    this.adminClient = new AdminClient(registry, access, this::callWith);
    this.remote = new RemoteCaller(allowList, () -> network);
    this.self = Caller.of(uuid);
    this.scheduler = Scheduler.system(name);
    this.notifications = new Notifications(registry, this, infos, constraints, scheduler, name);
    this.notificationClient = new NotificationClient(registry, this, infos,
        new NotificationClient.Registrar() {
          @Override
          public void register(Object listener) throws TRADEException {
            ContainerCore.this.register(listener, Set.of());
          }

          @Override
          public void registerSystem(Object listener) throws TRADEException {
            ContainerCore.this.registerSystem(listener);
          }

          @Override
          public void deregister(Object listener) throws TRADEException {
            ContainerCore.this.deregister(listener);
          }
        }, constraints, name);
    try {
      locks.bindCaller(registerSystem(new NotificationService(notifications, notificationClient,
          infos)));
      locks.bindCaller(registerSystem(locks.service()));
      registerSystem(new AdminService(new Administered(), access, settings.providerClasses(),
          System.currentTimeMillis()));
      for (Object service : hooks.services()) {
        registerSystem(service);
      }
    } catch (TRADEException e) {
      throw new IllegalStateException("a system service cannot be registered", e);
    }
    if (!settings.callLog().isEmpty()) {
      try {
        hooks.startCallLog(settings.callLog(), settings.callLogGroups());
      } catch (TRADEException e) {
        throw new IllegalArgumentException("CALLLOG=" + settings.callLog() + ": " + e.getMessage(),
            e);
      }
    }
    if (networked(settings)) {
      try {
        network = startNetwork();
      } catch (RuntimeException e) {
        scheduler.close();
        throw e;
      }
    }
  }

  private static boolean networked(Settings s) {
    return s.startAcceptingConnections() || !s.connectContainers().isEmpty()
        || s.startDiscovery() || s.startBroadcast();
  }

  private Network startNetwork() {
    Codec tables = new Codec(allowList, limits, InfoBinding.DESCRIPTORS, false);
    Network n = new Network(settings, uuid, name, host, registry, codec, tables, new Provider() {
      @Override
      public LocalService local(long serviceId) {
        return registry.local(serviceId);
      }

      @Override
      public Object invoke(Invocation call) throws TRADEException {
        return host(call);
      }
    }, scheduler);
    try {
      n.start();
    } catch (IOException e) {
      n.close();
      throw new UncheckedIOException(e);
    }
    return n;
  }

  /**
   * Registers the provider's services; their parameter and return types' packages join the
   * deserialization allow-list, so values of those types can arrive.
   */
  public List<LocalService> register(Object provider, Collection<String> groups) throws TRADEException {
    SystemGroup.refuse(groups);
    List<LocalService> services = registry.register(provider, groups);
    if (services.isEmpty()) {
      // Almost always a mistake (a missing annotation, a package-private method); the empty
      // result alone is easy to overlook.
      LOG.log(Level.WARNING, "registered a {0} in container {1} with no services: a service is a"
          + " public method annotated @TRADEService, on the class or on an interface it implements",
          provider.getClass().getName(), name);
    }
    for (LocalService s : services) {
      for (Class<?> p : s.parameterTypes()) {
        allowList.addPackageOf(p);
      }
      allowList.addPackageOf(s.returnType());
    }
    return services;
  }

  /** Registers one of the container's own providers in the reserved group. */
  private List<LocalService> registerSystem(Object provider) throws TRADEException {
    systemProviders.add(provider);
    return registry.register(provider, Set.of(SystemGroup.NAME));
  }

  /** The client of the middleware services (the static API's administrative methods). */
  public AdminClient admin() {
    return adminClient;
  }

  /**
   * Gives this container's service {@code serviceId} the groups {@code groups}; see
   * {@link Registry#setGroups}.
   */
  public void setGroups(long serviceId, Collection<String> groups) throws TRADEException {
    SystemGroup.refuse(groups);
    registry.setGroups(serviceId, groups);
  }

  /** The requester's side of notifications (the static API's client of the notification services). */
  public NotificationClient notifications() {
    return notificationClient;
  }

  /** Locks: the requester's side behind the static API (taking, releasing, listing). */
  public Locks locks() {
    return locks;
  }

  /** The requester's side of hooks (the static API's client of the hook services). */
  public HookClient hooks() {
    return hooks.client();
  }

  /**
   * Calls this container's system service {@code name} like any service (through the host chain).
   *
   * @throws TRADEException the service's own refusal, or a failure of the call
   */
  public <T> T callSystem(String name, Class<T> returnType, Object... args) throws TRADEException {
    return SystemServices.call(registry, this, id, name, returnType, args);
  }

  /**
   * Calls system service {@code name}, which returns a list of maps, in every container known
   * here, and joins the lists; a container that cannot be reached is left out.
   */
  public List<Map<String, Object>> callEverywhere(String name) {
    return SystemServices.collect(registry, this, name);
  }

  /** See {@link Registry#deregister}. */
  public void deregister(Object provider) throws TRADEServiceNotFoundException {
    registry.deregister(provider);
    systemProviders.remove(provider);
  }

  /** Deregisters every provider users registered here; returns how many. */
  public int reset() {
    int n = 0;
    for (Object p : registry.providers()) {
      if (!systemProviders.contains(p)) {
        try {
          registry.deregister(p);
          n++;
        } catch (TRADEServiceNotFoundException e) {
          // Deregistered meanwhile: gone either way.
        }
      }
    }
    return n;
  }

  /** This container's networking, started now if it was not running. */
  private synchronized Network network() {
    if (network == null) {
      network = startNetwork();
    }
    return network;
  }

  /**
   * Switches multicast discovery of other containers on or off (the TRADE paper's "turn on
   * discovery").
   *
   * @throws UncheckedIOException if discovery cannot open its socket
   */
  public void setDiscovery(boolean on) {
    if (on || network != null) {
      try {
        network().discovery().setDiscovery(on);
      } catch (IOException e) {
        throw new UncheckedIOException("cannot start discovery: " + e.getMessage(), e);
      }
    }
  }

  /** Switches announcing this container by multicast on or off. */
  public void setBroadcast(boolean on) {
    if (on || network != null) {
      try {
        network().discovery().setBroadcast(on);
      } catch (IOException e) {
        throw new UncheckedIOException("cannot start announcing: " + e.getMessage(), e);
      }
    }
  }

  public boolean isDiscovering() {
    Network n = network;
    return n != null && n.discovery().isDiscovering();
  }

  public boolean isBroadcasting() {
    Network n = network;
    return n != null && n.discovery().isBroadcasting();
  }

  /** The addresses this container accepts connections on (empty without networking). */
  public List<InetSocketAddress> listenAddresses() {
    Network n = network;
    return n == null ? List.of() : n.listenAddresses();
  }

  /** Ids of the containers with a direct link to this one. */
  public List<String> neighbours() {
    Network n = network;
    return n == null ? List.of() : n.neighbours();
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
  public int distance(ServiceDescriptor d) {
    Entry e = registry.entry(d);
    return e == null ? -1 : e.distance();
  }

  /**
   * The caller half, whose one job is routing: a service of this container goes through the host
   * chain here ({@link #callLocal}), any other to the {@link RemoteCaller}, which hands it to the
   * network; the host chain of the providing container runs it there. The arguments are
   * normalized and counted once, here, for both ways. A call made while a hook runs on this
   * thread carries the hooks running on its path ({@link HookPath}).
   */
  @Override
  public <T> T call(ServiceDescriptor d, Class<T> returnType, Object[] args, long timeoutNanos)
      throws TRADEException {
    Object[] normalized = Arguments.normalize(d, args);
    long timeout = timeoutNanos > 0 ? timeoutNanos : defaultTimeoutNanos;
    CallContext context = merged(access.ownContext(d), HookPath.current());
    return d.containerId().equals(id)
        ? callLocal(d, returnType, normalized, timeout, context)
        : remote.call(d, returnType, normalized, context, timeout);
  }

  /** As {@link #call}, with {@code context} (a proof of other credentials) and the default timeout. */
  private <T> T callWith(ServiceDescriptor d, Class<T> returnType, Object[] args,
      CallContext context) throws TRADEException {
    Object[] normalized = Arguments.normalize(d, args);
    return d.containerId().equals(id)
        ? callLocal(d, returnType, normalized, defaultTimeoutNanos, context)
        : remote.call(d, returnType, normalized, context, defaultTimeoutNanos);
  }

  /**
   * As {@link #call}, with the context of a call under {@code lock} (its id and this service's
   * fencing token) and, when {@code waitForLock}, the request to wait for a locked service.
   */
  @Override
  public <T> T callUnderLock(ServiceDescriptor d, UUID lock, boolean waitForLock,
      Class<T> returnType, Object[] args, long timeoutNanos) throws TRADEException {
    Object[] normalized = Arguments.normalize(d, args);
    long timeout = timeoutNanos > 0 ? timeoutNanos : defaultTimeoutNanos;
    CallContext context = merged(merged(access.ownContext(d), HookPath.current()),
        locks.client().context(d, lock, waitForLock));
    return d.containerId().equals(id)
        ? callLocal(d, returnType, normalized, timeout, context)
        : remote.call(d, returnType, normalized, context, timeout);
  }

  /** The entries of both contexts (their keys are the middleware's own, and never shared). */
  private static CallContext merged(CallContext a, CallContext b) {
    if (a.isEmpty()) {
      return b;
    }
    if (b.isEmpty()) {
      return a;
    }
    Map<String, String> all = new TreeMap<>(a.entries());
    all.putAll(b.entries());
    return CallContext.of(all);
  }

  /**
   * Calls the service without waiting, routed as {@link #call}. A remote call holds no thread while
   * its reply is outstanding (the link's reading thread completes it; the reply is decoded on this
   * container's asynchronous pool); a local call runs on that pool, through the host chain like any
   * call. Failures complete the future exceptionally with the {@code TRADEException} {@link #call}
   * would throw.
   */
  @Override
  public <T> CompletableFuture<T> callAsync(ServiceDescriptor d, Class<T> returnType, Object[] args,
      long timeoutNanos) {
    try {
      Object[] normalized = Arguments.normalize(d, args);
      long timeout = timeoutNanos > 0 ? timeoutNanos : defaultTimeoutNanos;
      CallContext context = merged(access.ownContext(d), HookPath.current());
      if (d.containerId().equals(id)) {
        return CompletableFuture.supplyAsync(() -> {
          try {
            return callLocal(d, returnType, normalized, timeout, context);
          } catch (TRADEException e) {
            throw new CompletionException(e);
          }
        }, asyncPool());
      }
      return remote.callAsync(d, returnType, normalized, context, timeout, asyncPool());
    } catch (TRADEException e) {
      return CompletableFuture.failedFuture(e);
    } catch (RejectedExecutionException e) {
      return CompletableFuture.failedFuture(CallErrors.gone(d, "container " + name + " is closed"));
    }
  }

  /** The pool of asynchronous calls, made at the first; refuses once the container is closed. */
  private synchronized ExecutorService asyncPool() {
    if (closed) {
      throw new RejectedExecutionException("container " + name + " is closed");
    }
    if (asyncPool == null) {
      AtomicInteger n = new AtomicInteger();
      asyncPool = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "trade-async-" + name + "-" + n.incrementAndGet());
        t.setDaemon(true);
        return t;
      });
    }
    return asyncPool;
  }

  /**
   * The host chain's links in the order every call passes them, the invoker last:
   * {@code access → locks → hooks → invoke} (access control first, so that nothing else sees a
   * refused call; hooks last, so that they see only calls that will run). With {@code hooks} null,
   * the same chain for the calls that no hook concerns.
   */
  private static List<CallLink> hostLinks(CallLink access, CallLink locks, CallLink hooks) {
    return hooks == null ? List.of(access, locks) : List.of(access, locks, hooks);
  }

  /**
   * Runs {@code call} through the host chain; a call no hook concerns skips the hooks link, which
   * would have passed it on untouched (an extra link costs as much as the rest of the chain).
   */
  private Object host(Invocation call) throws TRADEException {
    return hooks.concerns(call) ? hostChain.call(call) : bareChain.call(call);
  }

  private <T> T callLocal(ServiceDescriptor d, Class<T> returnType, Object[] args, long timeout,
      CallContext context) throws TRADEException {
    LocalService s = registry.local(d.serviceId());
    if (s == null) {
      throw CallErrors.gone(d, "it was deregistered");
    }
    Returns.check(d, returnType, s.returnType());
    if (copier == null) {
      return Returns.convert(d, returnType,
          host(Invocation.local(d, args, timeout, self, context)));
    }
    ClassLoader providerLoader = s.target().getClass().getClassLoader();
    if (providerLoader == null) {
      providerLoader = ClassLoader.getSystemClassLoader();
    }
    Object[] copies = new Object[args.length];
    for (int i = 0; i < args.length; i++) {
      copies[i] = copier.copy(args[i], providerLoader, s.declaredTypes());
    }
    Object result = host(Invocation.local(d, copies, timeout, self, context));
    return Returns.convert(d, returnType,
        copier.copy(result, RemoteCaller.callerLoader(returnType), s.declaredTypes()));
  }

  /** What the administration service acts on: this container. */
  private final class Administered implements AdminService.Container {
    @Override
    public String id() {
      return id;
    }

    @Override
    public String name() {
      return name;
    }

    @Override
    public String host() {
      return host;
    }

    @Override
    public void setDiscovery(boolean on) {
      ContainerCore.this.setDiscovery(on);
    }

    @Override
    public void setBroadcast(boolean on) {
      ContainerCore.this.setBroadcast(on);
    }

    @Override
    public boolean isDiscovering() {
      return ContainerCore.this.isDiscovering();
    }

    @Override
    public boolean isBroadcasting() {
      return ContainerCore.this.isBroadcasting();
    }

    @Override
    public boolean usesEncryption() {
      return settings.useEncryption();
    }

    @Override
    public InetSocketAddress listen(InetSocketAddress address) throws IOException {
      return network().listen(address);
    }

    @Override
    public List<InetSocketAddress> stopListening() {
      Network n = network;
      return n == null ? List.of() : n.stopListening();
    }

    @Override
    public List<InetSocketAddress> listenAddresses() {
      return ContainerCore.this.listenAddresses();
    }

    @Override
    public List<InetSocketAddress> announceable() {
      Network n = network;
      return n == null ? List.of() : n.announceable();
    }

    @Override
    public void connect(InetSocketAddress address) {
      network().connect(address);
    }

    @Override
    public boolean disconnect(UUID container) {
      Network n = network;
      return n != null && n.disconnect(container);
    }

    @Override
    public List<String> neighbours() {
      return ContainerCore.this.neighbours();
    }

    @Override
    public Map<String, Long> roundTrips() {
      Network n = network;
      return n == null ? Map.of() : n.roundTrips();
    }

    @Override
    public List<Map<String, Object>> callStatistics() {
      return hooks.statistics();
    }

    @Override
    public List<LocalService> services() {
      List<LocalService> result = new ArrayList<>();
      for (Object p : registry.providers()) {
        List<LocalService> s = registry.servicesOf(p);
        if (s != null) {
          result.addAll(s);
        }
      }
      return result;
    }

    @Override
    public List<LocalService> register(Object provider, Set<String> groups)
        throws TRADEException {
      return ContainerCore.this.register(provider, groups);
    }

    @Override
    public void deregister(Object provider) throws TRADEException {
      ContainerCore.this.deregister(provider);
    }

    @Override
    public int reset() {
      return ContainerCore.this.reset();
    }

    @Override
    public void setGroups(long serviceId, Set<String> groups) throws TRADEException {
      ContainerCore.this.setGroups(serviceId, groups);
    }

    @Override
    public void shutdownSoon() {
      // After the reply: it leaves when this call returns, and a container that closed first
      // would answer its caller with a lost link instead.
      CompletableFuture.runAsync(ContainerCore.this::close,
          CompletableFuture.delayedExecutor(SHUTDOWN_DELAY_MS, TimeUnit.MILLISECONDS));
    }
  }

  /** How long after replying a container shut down by its middleware service closes. */
  static final long SHUTDOWN_DELAY_MS = 200;

  /** Deregisters everything and stops; idempotent. */
  public void close() {
    if (!closed) {
      closed = true;
      // Notifications stop first: disconnecting makes every other container's services
      // unreachable from here, and reporting them as "left" would be false.
      notifications.close();
      locks.close();
      hooks.close();
      registry.deregisterAll();
      synchronized (this) {
        if (network != null) {
          network.close();
        }
        if (asyncPool != null) {
          asyncPool.shutdownNow();
        }
      }
      scheduler.close(); // last: networking's goodbyes may still be timed on it
    }
  }
}
