package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;

/**
 * What a hook costs the caller (docs/hooks.md): {@code small(int) -> boolean} without a hook, with
 * a local synchronous after hook and with an asynchronous one, in one container; and across two
 * containers linked over loopback (caller and wrapper in one, the service in the other), without a
 * hook, with a synchronous after hook (its wrapper is in the caller's container: one more round
 * trip, over the link the call came on) and with an asynchronous one; and a synchronous after hook
 * whose wrapper is in a third container, linked to the service's; and, for comparison, a service
 * that calls back a service of its caller's container (what a hook whose wrapper is there does,
 * without hooks). The paced ones call once a millisecond, like a control loop, so that an
 * asynchronous hook's wrapper call is over before the next call (back to back, it competes with
 * it for the cores). Sample time, so that JMH reports
 * p50 and p99. Needs a loopback interface (run it inside {@code unshare --net} with {@code lo} up).
 */
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Benchmark)
public class HookBench {
  /** The service. */
  public static class Arm {
    @TRADEService
    public boolean small(int x) {
      return (x & 1) == 0;
    }
  }

  /**
   * The pause before each paced call: a setup of each invocation, which JMH leaves out of the
   * time it measures.
   */
  @State(Scope.Thread)
  public static class Pace {
    @Setup(Level.Invocation)
    public void pause() {
      LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(1));
    }
  }

  /** A service that calls back a service of its caller's container before it answers. */
  public static class CallsBack {
    volatile TRADEServiceInfo back;

    @TRADEService
    public boolean callingBack(int x) throws Exception {
      return back.call(boolean.class, x);
    }
  }

  /** The wrappers: as cheap as a service can be, so that the hook's own cost shows. */
  public static class Wrappers {
    volatile int seen;

    @TRADEService
    public void noted(Object[] call) {
      seen++;
    }
  }

  private TRADEContainer plain;
  private TRADEContainer sync;
  private TRADEContainer async;
  private TRADEContainer caller;
  private TRADEContainer provider;
  private TRADEContainer third;
  private TRADEServiceInfo plainSmall;
  private TRADEServiceInfo syncSmall;
  private TRADEServiceInfo asyncSmall;
  private TRADEServiceInfo remotePlain;
  private TRADEServiceInfo remoteSync;
  private TRADEServiceInfo remoteAsync;
  private TRADEServiceInfo remoteThird;
  private TRADEServiceInfo remoteCallingBack;
  private int x;

  @Setup(Level.Trial)
  public void setUp() throws Exception {
    plain = container("plain");
    sync = container("sync");
    async = container("async");
    plainSmall = small(plain, "small");
    syncSmall = small(sync, "small");
    asyncSmall = small(async, "small");
    sync.afterService(small(sync, "noted"), syncSmall);
    async.afterService(small(async, "noted"), asyncSmall, true);

    caller = TRADEContainer.builder().name("caller").property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0").build();
    third = TRADEContainer.builder().name("third").property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0").build();
    provider = TRADEContainer.builder().name("provider").property("CONNECTCONTAINERS",
        caller.getServerAddresses().get(0) + "," + third.getServerAddresses().get(0)).build();
    third.registerAllServices(new Wrappers(), "wrappers");
    caller.registerAllServices(new Wrappers(), "wrappers");
    provider.registerAllServices(new Arm(), "plain");
    provider.registerAllServices(new Arm(), "sync");
    provider.registerAllServices(new Arm(), "async");
    provider.registerAllServices(new Arm(), "third");
    remotePlain = remote("plain");
    remoteSync = remote("sync");
    remoteAsync = remote("async");
    remoteThird = remote("third");
    caller.registerAllServices(new Arm(), "back");
    CallsBack callsBack = new CallsBack();
    provider.registerAllServices(callsBack, "callsBack");
    callsBack.back = provider.waitForService(new TRADEServiceConstraints().name("small")
        .inGroups("back"), java.time.Duration.ofSeconds(30));
    remoteCallingBack = caller.waitForService(new TRADEServiceConstraints().name("callingBack"),
        java.time.Duration.ofSeconds(30));
    TRADEServiceInfo noted = small(caller, "noted");
    caller.afterService(noted, remoteSync);
    caller.afterService(noted, remoteAsync, true);
    third.afterService(small(third, "noted"), third.waitForService(new TRADEServiceConstraints()
        .name("small").inGroups("third"), java.time.Duration.ofSeconds(30)));
  }

  private static TRADEContainer container(String name) throws Exception {
    TRADEContainer c = TRADEContainer.builder().name(name).build();
    c.registerAllServices(new Arm());
    c.registerAllServices(new Wrappers());
    return c;
  }

  private static TRADEServiceInfo small(TRADEContainer c, String name) throws Exception {
    return c.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  private TRADEServiceInfo remote(String group) throws Exception {
    return caller.waitForService(new TRADEServiceConstraints().name("small").inGroups(group),
        java.time.Duration.ofSeconds(30));
  }

  @TearDown(Level.Trial)
  public void tearDown() {
    for (TRADEContainer c : new TRADEContainer[] {plain, sync, async, provider, caller, third}) {
      c.close();
    }
  }

  @Benchmark
  public boolean localNoHook() throws Exception {
    return plainSmall.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean localSyncAfterHook() throws Exception {
    return syncSmall.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean localAsyncAfterHook() throws Exception {
    return asyncSmall.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteNoHook() throws Exception {
    return remotePlain.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteSyncAfterHook() throws Exception {
    return remoteSync.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteSyncAfterHookInAThirdContainer() throws Exception {
    return remoteThird.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteNoHookPaced(Pace pace) throws Exception {
    return remotePlain.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteAsyncAfterHookPaced(Pace pace) throws Exception {
    return remoteAsync.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteCallBack() throws Exception {
    return remoteCallingBack.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean remoteAsyncAfterHook() throws Exception {
    return remoteAsync.call(boolean.class, ++x);
  }
}
