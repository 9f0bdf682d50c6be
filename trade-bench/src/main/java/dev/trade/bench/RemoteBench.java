package dev.trade.bench;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Remote calls side by side: each system's server runs in its own JVM, this JVM is the client of
 * all of them. Latency is measured in interleaved rounds (round r runs every system in turn, the
 * order rotating with r), so that drift of the machine (other builds, frequency, noise) spreads over
 * all systems alike; throughput likewise, per number of concurrent callers.
 */
final class RemoteBench {
  /**
   * One latency scenario: a payload, how many calls per round, how long a round may take, and the
   * period at which calls start (0: each as soon as the one before returned).
   */
  private record Scenario(String name, int payload, int warmCalls, int callsPerRound,
      long roundLimitMs, long periodMicros) {}

  private final Path logs;
  private final boolean quick;
  private final int rounds;
  private final List<String> systems;

  RemoteBench(Path logs, boolean quick, List<String> systems) {
    this.logs = logs;
    this.quick = quick;
    this.rounds = quick ? 3 : 10;
    this.systems = systems;
  }

  private List<Scenario> scenarios() {
    int f = quick ? 10 : 1;
    return List.of(
        new Scenario("small", 0, 20_000 / f, 2_000 / f, 3_000, 0),
        new Scenario("1KB", 1024, 10_000 / f, 2_000 / f, 3_000, 0),
        new Scenario("1MB", 1 << 20, 100 / f, 30 / Math.min(f, 3), 5_000, 0),
        // A control loop's calls: one every millisecond, every thread idle in between.
        new Scenario("small_every_1ms", 0, 20_000 / f, 300 / f, 3_000, 1_000));
  }

  void run(Json json) throws Exception {
    Map<String, Jvm> servers = new LinkedHashMap<>();
    Map<String, Rpc> clients = new LinkedHashMap<>();
    try {
      for (String s : systems) {
        List<String> options = new ArrayList<>(List.of("-Xms256m", "-Xmx512m"));
        // For profiling: -Dbench.serverOptions="-XX:StartFlightRecording=filename=/tmp/%s.jfr"
        String extra = System.getProperty("bench.serverOptions", "").replace("%s", s);
        if (!extra.isBlank()) {
          options.addAll(List.of(extra.trim().split("\\s+")));
        }
        String classPath = s.equals("trade-alt")
            ? System.getProperty("bench.altClasspath") : System.getProperty("java.class.path");
        Jvm jvm = Jvm.start(classPath, options, ServerMain.class,
            logs.resolve("server-" + s + ".log"), s);
        servers.put(s, jvm);
      }
      for (String s : systems) {
        String address = servers.get(s).await("READY", 60_000);
        clients.put(s, Systems.connect(s, address));
        check(s, clients.get(s));
        System.err.println("connected to " + s + " at " + address);
      }
      json.key("latency").begin();
      for (Scenario sc : scenarios()) {
        latency(sc, clients, json);
      }
      json.end();
      json.key("throughput").begin();
      for (int callers : List.of(1, 16, 64)) {
        throughput(callers, clients, json);
      }
      json.end();
    } finally {
      for (Rpc c : clients.values()) {
        try {
          c.close();
        } catch (Exception e) {
          System.err.println("closing client: " + e);
        }
      }
      for (Jvm j : servers.values()) {
        j.close();
      }
    }
  }

  private static void check(String system, Rpc rpc) throws Exception {
    if (!rpc.small(42) || rpc.small(43) || rpc.consume(new byte[1024]) != 1024) {
      throw new IllegalStateException(system + " answered wrongly");
    }
  }

  private static byte[] payload(int size) {
    byte[] b = new byte[size];
    for (int i = 0; i < size; i++) {
      b[i] = (byte) (i * 31);
    }
    return b;
  }

  private static void call(Rpc rpc, byte[] data, int i) throws Exception {
    if (data == null) {
      if (rpc.small(i) != ((i & 1) == 0)) {
        throw new IllegalStateException("wrong answer");
      }
    } else if (rpc.consume(data) != data.length) {
      throw new IllegalStateException("wrong answer");
    }
  }

  private void latency(Scenario sc, Map<String, Rpc> clients, Json json) throws Exception {
    byte[] data = sc.payload == 0 ? null : payload(sc.payload);
    Map<String, Stats> stats = new LinkedHashMap<>();
    Map<String, List<Double>> roundP50 = new LinkedHashMap<>();
    for (String s : systems) {
      long until = System.nanoTime() + 20_000_000_000L;
      for (int i = 0; i < sc.warmCalls && System.nanoTime() < until; i++) {
        call(clients.get(s), data, i);
      }
      stats.put(s, new Stats(rounds * sc.callsPerRound));
      roundP50.put(s, new ArrayList<>());
    }
    for (int r = 0; r < rounds; r++) {
      for (int k = 0; k < systems.size(); k++) {
        String s = systems.get((k + r) % systems.size());
        Rpc rpc = clients.get(s);
        Stats round = new Stats(sc.callsPerRound);
        long start = System.nanoTime();
        long limit = start + sc.roundLimitMs * 1_000_000L;
        for (int i = 0; i < sc.callsPerRound && System.nanoTime() < limit; i++) {
          if (sc.periodMicros > 0) {
            // Starts on a fixed schedule: a late call does not push the later ones back.
            long due = start + (i + 1) * sc.periodMicros * 1_000L;
            for (long left; (left = due - System.nanoTime()) > 0; ) {
              LockSupport.parkNanos(left);
            }
          }
          long t0 = System.nanoTime();
          call(rpc, data, i);
          long dt = System.nanoTime() - t0;
          round.add(dt);
          stats.get(s).add(dt);
        }
        roundP50.get(s).add(round.percentileMicros(50));
      }
    }
    json.key(sc.name).begin();
    for (String s : systems) {
      json.key(s);
      stats.get(s).writeTo(json);
      System.err.printf("latency %-6s %-8s p50 %8.1f us  p99 %8.1f us%n", sc.name, s,
          stats.get(s).percentileMicros(50), stats.get(s).percentileMicros(99));
    }
    json.key("round_p50_us").begin();
    for (String s : systems) {
      json.key(s).beginArray();
      for (double v : roundP50.get(s)) {
        json.value(Stats.round(v));
      }
      json.endArray();
    }
    json.end();
    json.end();
  }

  private void throughput(int callers, Map<String, Rpc> clients, Json json) throws Exception {
    int tpRounds = quick ? 1 : 3;
    long warmMs = quick ? 200 : 500;
    long measureMs = quick ? 500 : 2_000;
    Map<String, List<Double>> rates = new LinkedHashMap<>();
    for (String s : systems) {
      rates.put(s, new ArrayList<>());
    }
    for (int r = 0; r < tpRounds; r++) {
      for (int k = 0; k < systems.size(); k++) {
        String s = systems.get((k + r) % systems.size());
        rates.get(s).add(rate(clients.get(s), callers, warmMs, measureMs));
      }
    }
    json.key(callers + "_callers").begin();
    for (String s : systems) {
      List<Double> v = new ArrayList<>(rates.get(s));
      v.sort(null);
      double median = v.get(v.size() / 2);
      json.key(s).begin();
      json.field("calls_per_s", Math.round(median));
      json.key("rounds").beginArray();
      for (double x : rates.get(s)) {
        json.value(Math.round(x));
      }
      json.endArray();
      json.end();
      System.err.printf("throughput %2d callers %-8s %,10.0f calls/s%n", callers, s, median);
    }
    json.end();
  }

  /** Calls per second of {@code callers} threads calling {@code small} as fast as they can. */
  private static double rate(Rpc shared, int callers, long warmMs, long measureMs) throws Exception {
    List<Rpc> perCaller = new ArrayList<>();
    for (int i = 0; i < callers; i++) {
      perCaller.add(shared.forCaller());
    }
    AtomicLong total = new AtomicLong();
    AtomicLong failures = new AtomicLong();
    AtomicInteger state = new AtomicInteger(); // 0 warm-up, 1 measure, 2 stop
    CountDownLatch started = new CountDownLatch(callers);
    List<Thread> threads = new ArrayList<>();
    for (int t = 0; t < callers; t++) {
      Rpc rpc = perCaller.get(t);
      Thread th = new Thread(() -> {
        long mine = 0;
        started.countDown();
        int i = 0;
        try {
          int p;
          while ((p = state.get()) < 2) {
            call(rpc, null, i++);
            if (p == 1 && state.get() == 1) {
              mine++;
            }
          }
        } catch (Exception e) {
          failures.incrementAndGet();
          System.err.println("caller failed: " + e);
        }
        total.addAndGet(mine);
      }, "caller-" + t);
      th.setDaemon(true);
      threads.add(th);
      th.start();
    }
    started.await();
    Thread.sleep(warmMs);
    long t0 = System.nanoTime();
    state.set(1);
    Thread.sleep(measureMs);
    state.set(2);
    long elapsed = System.nanoTime() - t0;
    for (Thread th : threads) {
      th.join(35_000);
    }
    for (Rpc rpc : perCaller) {
      if (rpc != shared) {
        rpc.close();
      }
    }
    if (failures.get() > 0) {
      throw new IllegalStateException(failures.get() + " callers failed");
    }
    return total.get() * 1e9 / elapsed;
  }
}
