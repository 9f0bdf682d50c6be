package dev.trade.examples.system;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.UUID;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;

/**
 * The churn soak of docs/reliability.md: for {@code <seconds>} (600 unless given), a newcomer
 * container joins every second and the oldest of the newcomers leaves, so that five are up at a
 * time; each newcomer is found by a staying container and called once. Beside them, a steady
 * caller calls a service of another staying container every 10 ms. All in this JVM, found by
 * multicast discovery on loopback (run it in a network namespace of its own, as src/reliability
 * does). Every ten seconds it prints the heap in use after full collections, the live threads and
 * the open file descriptors; at the end, their slopes per minute after the first minute (how long a
 * container keeps a departed one's state), and, once every newcomer is closed, whether threads and
 * descriptors came back to where they were before the first newcomer.
 *
 * <p>Exit status 0 when no call failed (steady or to a newcomer) and threads and descriptors came
 * back; 1 otherwise. The last line is the summary, {@code soak: ...}.
 */
public final class ChurnSoak {
  private static final int LIVE = 5;
  private static final long WAIT_NANOS = TimeUnit.SECONDS.toNanos(30);

  /** Every container's service: its name, and whom it answers. */
  public static final class Echo {
    private final String name;

    Echo(String name) {
      this.name = name;
    }

    @TRADEService
    public String soakEcho(String caller) {
      return name + " answers " + caller;
    }
  }

  private record Newcomer(TRADEContainer container, Future<?> check) {}

  private record Sample(double seconds, double heapMb, int threads, long fds, int listed) {}

  private final String sysId = "soak-" + UUID.randomUUID();
  private final String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
  private final AtomicLong steadyOk = new AtomicLong();
  private final AtomicLong steadyFailed = new AtomicLong();
  private final AtomicLong newcomersCalled = new AtomicLong();
  private final AtomicLong newcomersFailed = new AtomicLong();
  private final List<String> failures = new ArrayList<>();
  private final List<Sample> samples = new ArrayList<>();

  private ChurnSoak() {}

  public static void main(String[] args) throws Exception {
    int seconds = args.length > 0 ? Integer.parseInt(args[0]) : 600;
    System.exit(new ChurnSoak().run(seconds) ? 0 : 1);
  }

  private TRADEContainer build(String name) throws TRADEException {
    TRADEContainer c = TRADEContainer.builder().name(name).property("STARTDISCOVERY", "true")
        .property("STARTBROADCAST", "true").property("DISCOVERYRANGE", "localhost")
        .property("BROADCASTPORT", port).property("TRADESYSID", sysId).build();
    c.registerAllServices(new Echo(name), name);
    return c;
  }

  private boolean run(int seconds) throws Exception {
    try (TRADEContainer caller = build("s0"); TRADEContainer provider = build("s1")) {
      TRADEServiceConstraints steady = new TRADEServiceConstraints().inGroups("s1");
      await(() -> !caller.getAvailableServices(steady).isEmpty(), "s1 at s0");
      TRADEServiceInfo echo = caller.getAvailableService(steady);
      // One newcomer before the baseline: threads that the first one starts for good (shared
      // pools, timers) are not growth.
      try (TRADEContainer warmup = build("warmup")) {
        callNewcomer(caller, "warmup");
      }
      newcomersCalled.set(0);
      long start = System.nanoTime();
      Sample before = sample(0, caller);
      java.util.Set<String> threadsBefore = threadNames();
      ScheduledExecutorService ticks = Executors.newScheduledThreadPool(2); // the steady caller and the ticks
      ExecutorService checks = Executors.newSingleThreadExecutor();
      Deque<Newcomer> newcomers = new ArrayDeque<>();
      long[] joined = {0};
      ticks.scheduleAtFixedRate(() -> callSteadily(echo), 0, 10, TimeUnit.MILLISECONDS);
      ticks.scheduleAtFixedRate(() -> {
        try {
          String name = "n" + ++joined[0];
          TRADEContainer c = build(name);
          Future<?> check = checks.submit(() -> callNewcomer(caller, name));
          Newcomer oldest = null;
          synchronized (newcomers) {
            newcomers.addLast(new Newcomer(c, check));
            if (newcomers.size() > LIVE) {
              oldest = newcomers.removeFirst();
            }
          }
          if (oldest != null) {
            // It leaves once it was called: on a slow machine the tick runs late rather than a
            // newcomer leaving before it was found, which would count as a failed call.
            oldest.check.get();
            oldest.container.close();
          }
        } catch (RuntimeException | TRADEException | InterruptedException | ExecutionException e) {
          fail("newcomer " + joined[0] + " not started: " + e);
        }
      }, 1, 1, TimeUnit.SECONDS);
      for (int s = 10; s <= seconds; s += 10) {
        long due = start + TimeUnit.SECONDS.toNanos(s);
        while (System.nanoTime() - due < 0) {
          LockSupport.parkNanos(due - System.nanoTime());
        }
        samples.add(sample((System.nanoTime() - start) / 1e9, caller));
        Sample last = samples.get(samples.size() - 1);
        System.out.printf(Locale.ROOT, "soak %.0f s: heap %.1f MB, %d threads, %d fds, %d services listed;"
            + " steady calls %d ok, %d failed; newcomers %d joined, %d called, %d failed%n", last.seconds,
            last.heapMb, last.threads, last.fds, last.listed, steadyOk.get(), steadyFailed.get(), joined[0],
            newcomersCalled.get(), newcomersFailed.get());
      }
      ticks.shutdown();
      ticks.awaitTermination(30, TimeUnit.SECONDS);
      checks.shutdown();
      checks.awaitTermination(60, TimeUnit.SECONDS);
      synchronized (newcomers) {
        newcomers.forEach(n -> n.container.close());
        newcomers.clear();
      }
      boolean back = awaitQuietly(() -> threads() <= before.threads + 2 && fds() <= before.fds + 4);
      Sample after = sample((System.nanoTime() - start) / 1e9, caller);
      if (!back) {
        java.util.Set<String> extra = threadNames();
        extra.removeAll(threadsBefore);
        fail("threads or descriptors did not come back; threads started since: " + extra);
      }
      double from = seconds >= 120 ? 60 : seconds / 3.0;
      List<Sample> steadyState = samples.stream().filter(x -> x.seconds >= from).toList();
      String summary = String.format(Locale.ROOT, "soak: %d s, %d newcomers joined and left (%d called, %d"
          + " failed); steady calls %d ok, %d failed; slopes per minute after %.0f s: heap %+.2f MB,"
          + " threads %+.2f, fds %+.2f; before the first newcomer / after the last left: threads %d / %d,"
          + " fds %d / %d, heap %.1f / %.1f MB", seconds, joined[0], newcomersCalled.get(),
          newcomersFailed.get(), steadyOk.get(), steadyFailed.get(), from,
          slope(steadyState, Sample::heapMb), slope(steadyState, x -> x.threads),
          slope(steadyState, x -> x.fds), before.threads, after.threads, before.fds, after.fds,
          before.heapMb, after.heapMb);
      synchronized (failures) {
        failures.stream().limit(10).forEach(System.out::println);
      }
      System.out.println(summary);
      return steadyFailed.get() == 0 && newcomersFailed.get() == 0 && back && steadyOk.get() > 0;
    }
  }

  private void callSteadily(TRADEServiceInfo echo) {
    try {
      String answer = echo.call(String.class, "s0");
      if (!"s1 answers s0".equals(answer)) {
        throw new IllegalStateException("wrong answer " + answer);
      }
      steadyOk.incrementAndGet();
    } catch (Exception e) {
      steadyFailed.incrementAndGet();
      fail("steady call: " + e);
    }
  }

  /** Finds the newcomer from the staying caller and calls it, while it is up (five seconds). */
  private void callNewcomer(TRADEContainer caller, String name) {
    TRADEServiceConstraints its = new TRADEServiceConstraints().inGroups(name);
    try {
      await(() -> !caller.getAvailableServices(its).isEmpty(), name + " listed at s0");
      String answer = caller.getAvailableService(its).call(String.class, "s0");
      if (!(name + " answers s0").equals(answer)) {
        throw new IllegalStateException("wrong answer " + answer);
      }
      newcomersCalled.incrementAndGet();
    } catch (Exception e) {
      newcomersFailed.incrementAndGet();
      fail(name + ": " + e);
    }
  }

  private void fail(String what) {
    synchronized (failures) {
      failures.add(what);
    }
  }

  private static Sample sample(double seconds, TRADEContainer caller) {
    for (int i = 0; i < 3; i++) {
      System.gc();
    }
    double heap = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed() / 1e6;
    return new Sample(seconds, heap, threads(), fds(), caller.getAvailableServices().size());
  }

  private static java.util.Set<String> threadNames() {
    java.util.Set<String> names = new java.util.TreeSet<>();
    Thread.getAllStackTraces().keySet().forEach(t -> names.add(t.getName()));
    return names;
  }

  private static int threads() {
    return ManagementFactory.getThreadMXBean().getThreadCount();
  }

  /** Open file descriptors of this process (Linux), or -1 where /proc is not there. */
  private static long fds() {
    try (Stream<Path> s = Files.list(Path.of("/proc/self/fd"))) {
      return s.count();
    } catch (IOException e) {
      return -1;
    }
  }

  /** The least-squares slope of {@code y} over time, per minute. */
  private static double slope(List<Sample> s, java.util.function.ToDoubleFunction<Sample> y) {
    if (s.size() < 2) {
      return Double.NaN;
    }
    double mx = s.stream().mapToDouble(Sample::seconds).average().orElseThrow();
    double my = s.stream().mapToDouble(y).average().orElseThrow();
    double num = 0;
    double den = 0;
    for (Sample x : s) {
      num += (x.seconds - mx) * (y.applyAsDouble(x) - my);
      den += (x.seconds - mx) * (x.seconds - mx);
    }
    return num / den * 60;
  }

  /** Polls: these conditions have no event to wait on. */
  private static void await(BooleanSupplier condition, String what) {
    if (!awaitQuietly(condition)) {
      throw new IllegalStateException("not within 30 s: " + what);
    }
  }

  private static boolean awaitQuietly(BooleanSupplier condition) {
    long deadline = System.nanoTime() + WAIT_NANOS;
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        return false;
      }
      LockSupport.parkNanos(1_000_000);
    }
    return true;
  }
}
