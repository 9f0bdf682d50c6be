package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.BooleanSupplier;

/**
 * Containers coming and going, as components that restart all day: a few containers stay, and
 * newcomers join one after the other, each found, called and calling, then closed, until
 * {@code -Dbench.churnCycles} (3,000) have come and gone. All in this JVM, found by multicast
 * discovery on loopback. Every tenth of the way it records the heap in use after full
 * collections, the live threads, and the services the staying containers list: what the system
 * remembers of containers that left should level off once the first minute (how long a
 * container keeps a departed one's state) is over, not grow with every newcomer.
 *
 * <p>Not part of {@code src/run-benchmarks}, which it would lengthen by minutes without a goal to
 * judge; docs/benchmarks-log.md gives its command and results.
 */
final class Churn {
  private static final long WAIT_NANOS = 20_000_000_000L;
  private final int cycles = Integer.getInteger("bench.churnCycles", 3000);
  private final int staying = Integer.getInteger("bench.churnStaying", 5);

  /** The service every container provides: its name, and whom it answers. */
  public static final class Echo {
    private final String name;

    Echo(String name) {
      this.name = name;
    }

    @TRADEService
    public String churnEcho(String caller) {
      return name + " answers " + caller;
    }
  }

  void run(Json json) throws Exception {
    String sysId = "churn-" + UUID.randomUUID();
    String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
    List<TRADEContainer> stay = new ArrayList<>();
    long start = System.nanoTime();
    json.field("cycles", cycles).field("staying", staying);
    json.key("samples").beginArray();
    try {
      for (int i = 0; i < staying; i++) {
        stay.add(build(sysId, port, "s" + i));
      }
      TRADEContainer first = stay.get(0);
      await(() -> first.getAvailableServices().size() == staying, "the staying containers");
      for (int i = 1; i <= cycles; i++) {
        cycle(sysId, port, "n" + i, first, stay.get(i % staying));
        if (i % Math.max(1, cycles / 10) == 0) {
          sample(json, i, start, stay);
        }
      }
    } finally {
      stay.forEach(TRADEContainer::close);
    }
    json.endArray();
  }

  /** One newcomer: built, found and called by a staying container, calling one, closed, gone. */
  private static void cycle(String sysId, String port, String name, TRADEContainer first,
      TRADEContainer other) throws Exception {
    TRADEServiceConstraints its = new TRADEServiceConstraints().inGroups(name);
    TRADEServiceConstraints others = new TRADEServiceConstraints().inGroups(other.getName());
    try (TRADEContainer c = build(sysId, port, name)) {
      await(() -> !first.getAvailableServices(its).isEmpty(), name + " listed");
      check(first.getAvailableService(its).call(String.class, "s0"), name + " answers s0");
      await(() -> !c.getAvailableServices(others).isEmpty(), name + " listing " + other.getName());
      check(c.getAvailableService(others).call(String.class, name),
          other.getName() + " answers " + name);
    }
    await(() -> first.getAvailableServices(its).isEmpty(), name + " gone");
  }

  private static void sample(Json json, int cycle, long start, List<TRADEContainer> stay)
      throws InterruptedException {
    for (int i = 0; i < 3; i++) {
      System.gc();
      Thread.sleep(100);
    }
    long heap = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    int listed = 0;
    for (TRADEContainer c : stay) {
      listed += c.getAvailableServices().size();
    }
    int threads = ManagementFactory.getThreadMXBean().getThreadCount();
    double seconds = (System.nanoTime() - start) / 1e9;
    json.begin().field("cycle", cycle).field("seconds", Math.round(seconds * 10) / 10.0)
        .field("heap_mb", Math.round(heap / 1e5) / 10.0).field("threads", threads)
        .field("services_listed", listed).end();
    System.out.printf("churn %d: %.1f s, heap %.1f MB, %d threads, %d services listed%n", cycle,
        seconds, heap / 1e6, threads, listed);
  }

  private static TRADEContainer build(String sysId, String port, String name)
      throws TRADEException {
    TRADEContainer c = Lifecycle.discovering(TRADEContainer.builder().name(name), sysId, port)
        .build();
    c.registerAllServices(new Echo(name), name);
    return c;
  }

  private static void check(String answer, String expected) {
    if (!answer.equals(expected)) {
      throw new IllegalStateException("expected '" + expected + "', got '" + answer + "'");
    }
  }

  /** Polls: these conditions have no event to wait on, and the deadline fails the run. */
  private static void await(BooleanSupplier condition, String what) throws InterruptedException {
    long deadline = System.nanoTime() + WAIT_NANOS;
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        throw new IllegalStateException("not within 20 s: " + what);
      }
      Thread.sleep(1);
    }
  }
}
