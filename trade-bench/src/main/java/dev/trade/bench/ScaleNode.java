package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * One JVM of the scale benchmark: on {@code GO} it builds {@code count} containers one after the
 * other (discovery on loopback), each registering one service, prints {@code BUILT <epoch-us>} when
 * all are, and {@code CONVERGED <epoch-us>} once every one of them sees all
 * {@code total} services of the system (or {@code TIMEOUT <seen...>} 60 s after they were built).
 * Asked {@code CPU} (once every JVM converged) it prints {@code CPU <ms>}, the CPU time this JVM
 * used since GO. Then, asked {@code HEAP}, it prints
 * {@code HEAP <baseline> <after> <threads> <links> <most links>}: heap in use after full GCs
 * before the containers were built and with them running, and the links its containers hold, in
 * all and the most one of them holds. Then {@code AGAIN <system id> <port>} closes them, prints
 * {@code READY} and runs the same round (GO, BUILT, CONVERGED, CPU) as a new system in this JVM,
 * whose JIT has compiled what the first round ran. Exits when standard input closes (at most
 * 10 min).
 *
 * <p>With {@code -Dbench.progress=true} it also writes to standard error (the JVM's log) how long
 * each container took to build and register, and once a second until convergence how many
 * services its least and its best informed containers see, and which is the least informed and
 * how many links it has.
 *
 * <p>With {@code -Dbench.startTogether=true} it builds its containers all at once, each on a thread
 * of its own, as a launcher starting a whole system does (not part of the published figures).
 * With {@code -Dbench.scaleProfiler} it profiles each round ({@link RoundProfile}).
 *
 * <p>Arguments: system id, broadcast port, count, total, name prefix.
 */
public final class ScaleNode {
  /** Each container's one service. */
  public static final class Probe {
    @TRADEService
    public int scaleProbe() {
      return 1;
    }
  }

  private ScaleNode() {}

  /** CPU time of this whole JVM so far (all threads: JIT and GC included). */
  private static long processCpuNanos() {
    return ((com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
        .getProcessCpuTime();
  }

  /** The names {@code Scale} gives the containers of a system of {@code total}. */
  private static List<String> expectedNames(int total) {
    List<String> names = new ArrayList<>(List.of("c0-0"));
    int left = total - 1;
    for (int k = 1; left > 0; k++) {
      for (int i = 0; i < Math.min(Scale.PER_JVM, left); i++) {
        names.add("c" + k + "-" + i);
      }
      left -= Scale.PER_JVM;
    }
    return names;
  }

  public static void main(String[] args) throws Exception {
    String sysId = args[0];
    String port = args[1];
    int count = Integer.parseInt(args[2]);
    int total = Integer.parseInt(args[3]);
    String prefix = args[4];
    Thread watchdog = new Thread(() -> {
      try {
        Thread.sleep(10 * 60_000L);
      } catch (InterruptedException e) {
        return;
      }
      Runtime.getRuntime().halt(3);
    });
    watchdog.setDaemon(true);
    watchdog.start();
    // Load and initialise TRADE's classes before the baseline.
    try (TRADEContainer warm = TRADEContainer.builder().name("warm").build()) {
      warm.registerAllServices(new Probe());
      warm.getAvailableServices(new TRADEServiceConstraints().name("scaleProbe"));
    }
    long baseline = usedHeapAfterGc();
    BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
    System.out.println("READY");
    System.out.flush();
    List<TRADEContainer> containers = round(in, sysId, port, count, total, prefix);
    if (containers == null || !"HEAP".equals(in.readLine())) {
      return;
    }
    long after = usedHeapAfterGc();
    int links = 0;
    int mostLinks = 0;
    for (TRADEContainer c : containers) {
      int n = c.getNeighbours().size();
      links += n;
      mostLinks = Math.max(mostLinks, n);
    }
    System.out.println("HEAP " + baseline + " " + after + " "
        + ManagementFactory.getThreadMXBean().getThreadCount() + " " + links + " " + mostLinks);
    System.out.flush();
    for (String line; (line = in.readLine()) != null; ) {
      // AGAIN <system id> <port>: the same round once more, in this JVM whose JIT has now compiled
      // what converging runs, as a new system beside the closed one.
      if (line.startsWith("AGAIN ")) {
        for (TRADEContainer c : containers) {
          c.close();
        }
        String[] a = line.split(" ");
        usedHeapAfterGc(); // the closed system's garbage, collected before GO as for the first round
        System.out.println("READY");
        System.out.flush();
        containers = round(in, a[1], a[2], count, total, prefix);
        if (containers == null) {
          return;
        }
      }
    }
    for (TRADEContainer c : containers) {
      c.close();
    }
    System.exit(0);
  }

  /**
   * One round: on {@code GO} builds the containers, reports {@code BUILT} and {@code CONVERGED} (or
   * {@code TIMEOUT}), then on {@code CPU} the CPU time since {@code GO}. Returns the containers, or
   * null when the input ended or said something else.
   */
  private static List<TRADEContainer> round(BufferedReader in, String sysId, String port,
      int count, int total, String prefix) throws Exception {
    if (!"GO".equals(in.readLine())) {
      return null;
    }
    // One after the other unless told otherwise, as the published figures were always measured:
    // started all at once, 25 containers per JVM on 2 cores once left some of them without any
    // other container's service after a minute (see docs/benchmarks-log.md, "Started together").
    List<TRADEContainer> containers = new ArrayList<>();
    boolean progress = Boolean.getBoolean("bench.progress");
    long go = System.nanoTime();
    long goCpu = processCpuNanos();
    boolean profiling = RoundProfile.start();
    if (Boolean.getBoolean("bench.startTogether")) {
      containers.addAll(buildTogether(sysId, port, count, prefix));
    }
    for (int i = containers.size(); i < count; i++) {
      long t0 = System.nanoTime();
      TRADEContainer c = build(sysId, port, prefix + i);
      long t1 = System.nanoTime();
      c.registerAllServices(new Probe());
      containers.add(c);
      if (progress) {
        System.err.printf("BUILD %s: build %d ms, register %d ms%n", c.getName(), (t1 - t0) / 1_000_000,
            (System.nanoTime() - t1) / 1_000_000);
      }
    }
    System.out.println("BUILT " + Clock.epochMicros());
    TRADEServiceConstraints probe = new TRADEServiceConstraints().name("scaleProbe");
    long until = System.nanoTime() + 60_000_000_000L;
    boolean converged = false;
    long report = System.nanoTime();
    // Containers not yet seen with every service, in order: each poll asks them up to the first
    // that lacks some, and all containers once none is left. Asking from the first container at
    // every poll, as before, was 6 % of a scale JVM's allocation (whose collections pause all 25
    // containers) once the first ones had converged.
    List<TRADEContainer> pending = new ArrayList<>(containers);
    while (System.nanoTime() < until) {
      Iterator<TRADEContainer> it = pending.iterator();
      while (it.hasNext() && it.next().getAvailableServices(probe).size() >= total) {
        it.remove();
      }
      if (pending.isEmpty()) {
        for (TRADEContainer c : containers) {
          if (c.getAvailableServices(probe).size() < total) {
            pending.add(c);
          }
        }
        converged = pending.isEmpty();
        if (converged) {
          break;
        }
      }
      if (progress && System.nanoTime() - report >= 1_000_000_000L) {
        report = System.nanoTime();
        int least = Integer.MAX_VALUE;
        int most = 0;
        TRADEContainer laggard = null;
        for (TRADEContainer c : containers) {
          int seen = c.getAvailableServices(probe).size();
          if (seen < least) {
            least = seen;
            laggard = c;
          }
          most = Math.max(most, seen);
        }
        System.err.printf("PROGRESS %d ms after GO: %d..%d of %d services (the fewest: %s, %d links)%n",
            (report - go) / 1_000_000, least, most, total, laggard.getName(),
            laggard.getNeighbours().size());
        if (least >= total - 3) {
          // The last few: who lacks whose service, to tell a slow link from a slow table.
          for (TRADEContainer c : containers) {
            Collection<TRADEServiceInfo> seen = c.getAvailableServices(probe);
            if (seen.size() < total) {
              List<String> missing = expectedNames(total);
              seen.forEach(i -> missing.remove(i.getContainerName()));
              System.err.printf("LACKING %s lacks %s; %d links%n", c.getName(), missing,
                  c.getNeighbours().size());
            }
          }
        }
      }
      Thread.sleep(10);
    }
    long ended = Clock.epochMicros();
    if (profiling) {
      RoundProfile.save(prefix);
    }
    if (converged) {
      System.out.println("CONVERGED " + ended);
    } else {
      StringBuilder seen = new StringBuilder("TIMEOUT");
      for (TRADEContainer c : containers) {
        seen.append(' ').append(c.getAvailableServices(probe).size());
      }
      System.out.println(seen);
    }
    System.out.flush();
    // The other JVMs may still be converging; measure once everyone is done, every JVM at once
    // (asked one after the other for their heaps, the later ones would count the time the
    // earlier ones spend in full collections).
    if (!"CPU".equals(in.readLine())) {
      return null;
    }
    System.out.println("CPU " + (processCpuNanos() - goCpu) / 1_000_000);
    System.out.flush();
    return containers;
  }

  /** A container of the system {@code sysId}, discovering on loopback at {@code port}. */
  private static TRADEContainer build(String sysId, String port, String name) {
    return Lifecycle.discovering(TRADEContainer.builder().name(name), sysId, port).build();
  }

  private static List<TRADEContainer> buildTogether(String sysId, String port, int count,
      String prefix) throws InterruptedException, ExecutionException {
    ExecutorService pool = Executors.newFixedThreadPool(count);
    try {
      List<Future<TRADEContainer>> building = new ArrayList<>();
      for (int i = 0; i < count; i++) {
        String name = prefix + i;
        building.add(pool.submit(() -> {
          TRADEContainer c = build(sysId, port, name);
          c.registerAllServices(new Probe());
          return c;
        }));
      }
      List<TRADEContainer> built = new ArrayList<>();
      for (Future<TRADEContainer> f : building) {
        built.add(f.get());
      }
      return built;
    } finally {
      pool.shutdown();
    }
  }

  private static long usedHeapAfterGc() throws InterruptedException {
    for (int i = 0; i < 3; i++) {
      System.gc();
      Thread.sleep(100);
    }
    return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
  }
}
