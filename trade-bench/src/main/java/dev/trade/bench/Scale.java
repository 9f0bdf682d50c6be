package dev.trade.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/**
 * N containers on one host (N = 10, 50, 100), found by multicast discovery on loopback: the time
 * from "go" until every container sees every container's service, and the heap each container
 * costs. 100 JVMs of ~40 MB resident each would mostly measure JVM start-up on 2 cores, so the
 * containers run in a few JVMs ({@link ScaleNode}, at most 25 each, containers of one JVM are as
 * separate as in different JVMs: own sockets, threads and tables), plus one JVM that holds a single
 * container under {@code -Xmx16m}: direct proof that one container of an N-container system fits
 * in 16 MB, next to the average heap per container of the big JVMs.
 *
 * <p>Each size runs {@code -Dbench.scaleRuns} times (3, or 1 for a quick run), each a new system
 * of new JVMs: one run's convergence time varies by a third from run to run on a loaded 2-core
 * machine, so the report judges the median.
 *
 * <p>Each run then closes its containers and builds them again in the same JVMs, as a new system
 * ({@code -Dbench.scaleWarm=false} skips this): the same work with the JIT's compilation of it
 * mostly done, which tells how much of the first round was the JVMs warming up. The goal is judged
 * on the first round, the containers a JVM starts with.
 */
final class Scale {
  static final int PER_JVM = 25;
  private final Path logs;
  private final boolean quick;
  private final boolean warmRound = Boolean.parseBoolean(System.getProperty("bench.scaleWarm", "true"));

  Scale(Path logs, boolean quick) {
    this.logs = logs;
    this.quick = quick;
  }

  void run(Json json) throws Exception {
    json.key("sizes").beginArray();
    String sizes = System.getProperty("bench.scaleSizes", quick ? "10" : "10,50,100");
    int runs = Integer.getInteger("bench.scaleRuns", quick ? 1 : 3);
    for (String n : sizes.split(",")) {
      for (int run = 0; run < runs; run++) {
        once(Integer.parseInt(n.trim()), json);
      }
    }
    json.endArray();
  }

  private void once(int n, Json json) throws Exception {
    String sysId = "scale-" + Long.toHexString(ThreadLocalRandom.current().nextLong());
    String port = Integer.toString(40_000 + ThreadLocalRandom.current().nextInt(20_000));
    List<Integer> counts = new ArrayList<>();
    counts.add(1); // the -Xmx16m JVM
    for (int left = n - 1; left > 0; left -= PER_JVM) {
      counts.add(Math.min(PER_JVM, left));
    }
    List<Jvm> jvms = new ArrayList<>();
    try {
      for (int k = 0; k < counts.size(); k++) {
        String heap = k == 0 ? "-Xmx16m" : "-Xmx1g";
        List<String> options = new ArrayList<>(List.of(heap, "-Xss512k",
            "-Dbench.progress=" + Boolean.getBoolean("bench.progress"),
            "-Dbench.startTogether=" + Boolean.getBoolean("bench.startTogether")));
        // For profiling the first big JVM: -Dbench.nodeOptions=-XX:StartFlightRecording=filename=x.jfr
        String extra = System.getProperty("bench.nodeOptions", "");
        if (k == 1 && !extra.isBlank()) {
          options.addAll(List.of(extra.trim().split("\\s+")));
        }
        jvms.add(Jvm.start(Jvm.tradeClassPath(), options, ScaleNode.class,
            logs.resolve("scale-" + n + "-" + k + ".log"), sysId, port,
            Integer.toString(counts.get(k)), Integer.toString(n), "c" + k + "-"));
      }
      for (Jvm j : jvms) {
        j.await("READY", 60_000);
      }
      Round cold = go(jvms);
      StringBuilder problems = new StringBuilder(cold.problems);
      List<long[]> heaps = new ArrayList<>();
      for (int k = 0; k < jvms.size(); k++) {
        try {
          jvms.get(k).send("HEAP");
          String[] h = jvms.get(k).await("HEAP", 60_000).split(" ");
          heaps.add(new long[] {Long.parseLong(h[0]), Long.parseLong(h[1]), Long.parseLong(h[2]),
              Long.parseLong(h[3]), Long.parseLong(h[4])});
        } catch (IOException e) {
          heaps.add(null);
          problems.append("JVM ").append(k).append(" (").append(counts.get(k))
              .append(k == 0 ? " container, -Xmx16m" : " containers").append(") gave no heap figure: ")
              .append(e.getMessage()).append("; ");
        }
      }
      // The same round again in the same JVMs, as a new system: their JIT has compiled what
      // converging runs, so this tells how much of the first round was the JVMs' warming up.
      Round warm = null;
      if (warmRound) {
        String again = "AGAIN " + sysId + "-warm "
            + (40_000 + ThreadLocalRandom.current().nextInt(20_000));
        try {
          for (Jvm j : jvms) {
            j.send(again);
          }
          for (Jvm j : jvms) {
            j.await("READY", 60_000);
          }
          warm = go(jvms);
        } catch (IOException e) {
          problems.append("the warm round did not start: ").append(e.getMessage()).append("; ");
        }
      }
      long bigHeap = 0;
      int bigCount = 0;
      long threads = 0;
      long links = 0;
      long mostLinks = 0;
      for (int k = 0; k < jvms.size(); k++) {
        long[] h = heaps.get(k);
        if (h != null) {
          threads += h[2];
          links += h[3];
          mostLinks = Math.max(mostLinks, h[4]);
          if (k > 0) {
            bigHeap += h[1] - h[0];
            bigCount += counts.get(k);
          }
        }
      }
      long[] single = heaps.get(0);
      json.begin();
      json.field("containers", n);
      json.field("jvms", jvms.size());
      json.field("converged", cold.converged);
      json.field("convergence_ms", cold.convergenceMs());
      json.field("all_built_ms", cold.builtMs());
      json.field("problems", problems.toString());
      json.field("heap_per_container_mb", bigCount == 0 ? null : Math.round(bigHeap / (double) bigCount / 1e4) / 100.0);
      json.field("single_container_jvm_xmx16m_heap_mb",
          single == null ? null : Math.round((single[1] - single[0]) / 1e4) / 100.0);
      json.field("single_container_jvm_total_heap_mb", single == null ? null : Math.round(single[1] / 1e4) / 100.0);
      json.field("threads_total", threads);
      // The links a container holds, on average: each link counts at both of its ends.
      json.field("links_per_container", Math.round(links * 10.0 / n) / 10.0);
      json.field("most_links", mostLinks);
      // All JVMs' CPU time from GO until every one converged: the work converging took, which a
      // busy machine stretches less than the wall-clock time.
      json.field("cpu_seconds", cold.cpuSeconds());
      if (warm != null) {
        json.field("warm_converged", warm.converged);
        json.field("warm_convergence_ms", warm.convergenceMs());
        json.field("warm_all_built_ms", warm.builtMs());
        json.field("warm_cpu_seconds", warm.cpuSeconds());
        json.field("warm_problems", warm.problems);
      }
      json.end();
      System.err.printf("scale %d: converged=%s in %.0f ms, heap/container %.2f MB, threads %d, links/container %.1f %s%n",
          n, cold.converged, cold.convergenceMs(), bigCount == 0 ? -1 : bigHeap / (double) bigCount / 1e6, threads,
          links / (double) n, problems);
      if (warm != null) {
        System.err.printf("scale %d warm: converged=%s in %.0f ms, %.1f CPU-s %s%n", n,
            warm.converged, warm.convergenceMs(), warm.cpuSeconds(), warm.problems);
      }
    } finally {
      for (Jvm j : jvms) {
        j.close();
      }
    }
  }

  /** What one round measured; times in epoch µs. */
  private record Round(long go, long built, long last, boolean converged, long cpuMillis,
      String problems) {
    Double convergenceMs() {
      return converged ? (last - go) / 1e3 : null;
    }

    Double builtMs() {
      return built == 0 ? null : (built - go) / 1e3;
    }

    double cpuSeconds() {
      return Math.round(cpuMillis / 100.0) / 10.0;
    }
  }

  /** Sends GO to every JVM and waits for each to converge (or give up), then asks their CPU. */
  private static Round go(List<Jvm> jvms) throws IOException, InterruptedException {
    long go = Clock.epochMicros();
    for (Jvm j : jvms) {
      j.send("GO");
    }
    long last = 0;
    long built = 0;
    boolean converged = true;
    StringBuilder problems = new StringBuilder();
    for (int k = 0; k < jvms.size(); k++) {
      String line;
      try {
        line = jvms.get(k).await("", 90_000);
        if (line.startsWith("BUILT")) {
          built = Math.max(built, Long.parseLong(line.substring(6).trim()));
          line = jvms.get(k).await("", 90_000);
        }
      } catch (IOException e) {
        line = "JVM " + k + ": " + e.getMessage();
      }
      if (line.startsWith("CONVERGED")) {
        last = Math.max(last, Long.parseLong(line.substring(10).trim()));
      } else {
        converged = false;
        problems.append(line.length() > 300 ? line.substring(0, 300) + "..." : line).append("; ");
      }
    }
    // CPU first, from every JVM at once: the work until convergence, not the full collections
    // of the heap measurement below.
    long cpuMillis = 0;
    for (Jvm j : jvms) {
      try {
        j.send("CPU");
      } catch (IOException e) {
        // Its answer is missed below.
      }
    }
    for (int k = 0; k < jvms.size(); k++) {
      try {
        cpuMillis += Long.parseLong(jvms.get(k).await("CPU", 60_000));
      } catch (IOException e) {
        problems.append("JVM ").append(k).append(" gave no CPU figure: ").append(e.getMessage())
            .append("; ");
      }
    }
    return new Round(go, built, last, converged, cpuMillis, problems.toString());
  }
}
