package dev.trade.bench;

import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Runs one part of the benchmark and writes its results as JSON into a directory:
 * {@code remote} (latency and throughput against the peers), {@code lifecycle} (start to callable,
 * kill to left), {@code scale} (10/50/100 containers) and {@code machine} (facts about this host).
 * {@code src/run-benchmarks} runs them all; {@code -Dbench.quick=true} makes a short smoke run.
 * {@code churn} (containers coming and going, {@link Churn}), {@code notify} (notifications and
 * non-blocking calls, {@link NotifyBench}) and {@code proxycpu} (a typed proxy against a direct
 * call, {@link ProxyCpu}) are run by hand.
 */
public final class BenchMain {
  private BenchMain() {}

  public static void main(String[] args) throws Throwable {
    if (args.length < 2) {
      System.err.println("usage: BenchMain remote|lifecycle|scale|localcpu|proxycpu|machine|churn|notify <results-dir> [systems...]");
      System.exit(2);
    }
    Path out = Path.of(args[1]);
    Files.createDirectories(out);
    Path logs = out.resolve("logs");
    boolean quick = Boolean.getBoolean("bench.quick");
    Json json = new Json().begin();
    json.field("quick", quick);
    json.field("load_average_before", loadAverage());
    json.field("cpu_index_ms", Calibration.medianMillis());
    long started = System.nanoTime();
    switch (args[0]) {
      case "remote" -> {
        List<String> systems = args.length > 2 ? List.of(args).subList(2, args.length) : Systems.ALL;
        new RemoteBench(logs, quick, systems).run(json);
      }
      case "lifecycle" -> new Lifecycle(logs, quick).run(json);
      case "scale" -> new Scale(logs, quick).run(json);
      case "machine" -> machine(json);
      case "localcpu" -> LocalCpu.run(json);
      case "proxycpu" -> ProxyCpu.run(json);
      case "churn" -> new Churn().run(json);
      case "notify" -> new NotifyBench(logs, quick).run(json);
      default -> throw new IllegalArgumentException("unknown part " + args[0]);
    }
    json.field("load_average_after", loadAverage());
    json.field("wall_s", Math.round((System.nanoTime() - started) / 1e8) / 10.0);
    json.end();
    Files.writeString(out.resolve(args[0] + ".json"), json + "\n", StandardCharsets.UTF_8);
    System.exit(0);
  }

  private static void machine(Json json) throws Exception {
    json.field("cores", Runtime.getRuntime().availableProcessors());
    json.field("jdk", System.getProperty("java.vm.name") + " " + System.getProperty("java.runtime.version"));
    json.field("os", System.getProperty("os.name") + " " + System.getProperty("os.version")
        + " " + System.getProperty("os.arch"));
    String cpu = "";
    for (String line : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
      if (line.startsWith("model name")) {
        cpu = line.substring(line.indexOf(':') + 1).trim();
        break;
      }
    }
    json.field("cpu", cpu);
    var os = (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
    json.field("memory_gb", Math.round(os.getTotalMemorySize() / 1e9));
  }

  /** The 1-minute load average: how busy the machine was besides us. */
  static double loadAverage() {
    return Math.round(ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage() * 100) / 100.0;
  }
}
