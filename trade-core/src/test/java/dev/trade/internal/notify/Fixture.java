package dev.trade.internal.notify;

import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.internal.call.Arguments;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.LocalInvoker;
import dev.trade.internal.call.Returns;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.testing.FakeScheduler;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;

/**
 * One container's notification engine on a fake clock: a real registry, services called through
 * the terminal link of the host chain, deliveries held until the test runs them.
 */
final class Fixture {
  final Registry registry = new Registry("c1", "one", "host");
  final FakeScheduler clock = new FakeScheduler();
  final ManualExecutor deliveries = new ManualExecutor();
  final ManualExecutor events = new ManualExecutor();
  final Notifications engine;

  /** Deliveries held until the test runs them. */
  Fixture() {
    this(null);
  }

  /** Deliveries on {@code pool} (real threads), or held until the test runs them (null). */
  Fixture(Executor pool) {
    engine = new Notifications(registry, new Caller(), InfoBinding.DESCRIPTORS,
        argument -> argument == null ? new Query(null, null, null, Set.of(), Set.of(), false, null,
            null, Set.of(), List.of(), List.of()) : null, clock, pool != null ? pool : deliveries,
        events, "one");
  }

  /** Registers {@code provider} and returns its service {@code name}. */
  ServiceDescriptor service(Object provider, String name) throws TRADEException {
    List<LocalService> services = registry.servicesOf(provider);
    if (services == null) {
      services = registry.register(provider, Set.of());
    }
    for (LocalService s : services) {
      if (s.descriptor().name().equals(name)) {
        return s.descriptor();
      }
    }
    throw new AssertionError("no service " + name);
  }

  /**
   * Moves the clock, then runs every delivery it made due; a delivery handed over before its due
   * time (which would wait for it) stays queued.
   */
  void advanceAndDeliver(long millis) {
    clock.advanceMillis(millis);
    deliveries.runAll(r -> !(r instanceof Notifications.Delivery)
        || ((Notifications.Delivery) r).dueNanos - clock.nanoTime() <= 0);
    events.runAll();
  }

  String request(String type, Object argument, ServiceDescriptor service, ServiceDescriptor callback)
      throws TRADEException {
    return engine.request(type, argument, service == null ? List.of() : List.of(service), callback,
        "tester");
  }

  private final class Caller implements ServiceCaller {
    private final LocalInvoker invoker = new LocalInvoker(registry);

    @Override
    public String containerId() {
      return registry.containerId();
    }

    @Override
    public int distance(ServiceDescriptor service) {
      return 0;
    }

    @Override
    public <T> T call(ServiceDescriptor d, Class<T> returnType, Object[] args, long timeoutNanos)
        throws TRADEException {
      Object r = invoker.proceed(Invocation.local(d, Arguments.normalize(d, args), timeoutNanos,
          dev.trade.internal.call.Caller.of(new java.util.UUID(0, 1)),
          CallContext.EMPTY), null);
      return Returns.convert(d, returnType, r);
    }

    @Override
    public <T> CompletableFuture<T> callAsync(ServiceDescriptor d, Class<T> returnType,
        Object[] args, long timeoutNanos) {
      throw new UnsupportedOperationException();
    }
  }

  /** A condition and a value source. */
  public static final class Battery {
    volatile boolean low;
    volatile int level = 100;
    int reads;

    @TRADEService
    public boolean isLowBattery() {
      reads++;
      return low;
    }

    @TRADEService
    public int level() {
      return level--;
    }

    @TRADEService
    public int levelOrFail() {
      throw new IllegalStateException("sensor unplugged");
    }

    @TRADEService
    public String notACondition() {
      return "yes";
    }

    @TRADEService
    public int add(int a, int b) {
      return a + b;
    }
  }

  /** Callbacks that record what they get. */
  public static final class Sink {
    final List<String> got = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void tick() {
      got.add("tick");
    }

    @TRADEService
    public void value(Integer v) {
      got.add("value " + v);
    }

    @TRADEService
    public void valueOrFailure(Object v, Throwable failure) {
      got.add(failure == null ? "value " + v : "failure " + failure.getMessage());
    }

    @TRADEService
    public void text(String s) {
      got.add("text " + s);
    }

    @TRADEService
    public void fails() {
      got.add("fails");
      throw new IllegalStateException("callback broke");
    }
  }
}
