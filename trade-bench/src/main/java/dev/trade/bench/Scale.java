package dev.trade.bench;

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
 */
final class Scale {
  private static final int PER_JVM = 25;
  private final Path logs;
  private final boolean quick;

  Scale(Path logs, boolean quick) {
    this.logs = logs;
    this.quick = quick;
  }

  void run(Json json) throws Exception {
    json.key("sizes").beginArray();
    for (int n : quick ? List.of(10) : List.of(10, 50, 100)) {
      once(n, json);
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
        jvms.add(Jvm.start(List.of(heap, "-Xss512k"), ScaleNode.class,
            logs.resolve("scale-" + n + "-" + k + ".log"), sysId, port,
            Integer.toString(counts.get(k)), Integer.toString(n), "c" + k + "-"));
      }
      for (Jvm j : jvms) {
        j.await("READY", 60_000);
      }
      long go = Clock.epochMicros();
      for (Jvm j : jvms) {
        j.send("GO");
      }
      long last = 0;
      boolean converged = true;
      StringBuilder problems = new StringBuilder();
      for (Jvm j : jvms) {
        String line = j.await("", 90_000);
        if (line.startsWith("CONVERGED")) {
          last = Math.max(last, Long.parseLong(line.substring(10).trim()));
        } else {
          converged = false;
          problems.append(line).append("; ");
        }
      }
      List<long[]> heaps = new ArrayList<>();
      for (Jvm j : jvms) {
        j.send("HEAP");
        String[] h = j.await("HEAP", 60_000).split(" ");
        heaps.add(new long[] {Long.parseLong(h[0]), Long.parseLong(h[1]), Long.parseLong(h[2])});
      }
      long bigHeap = 0;
      int bigCount = 0;
      for (int k = 1; k < jvms.size(); k++) {
        bigHeap += heaps.get(k)[1] - heaps.get(k)[0];
        bigCount += counts.get(k);
      }
      json.begin();
      json.field("containers", n);
      json.field("jvms", jvms.size());
      json.field("converged", converged);
      json.field("convergence_ms", converged ? (last - go) / 1e3 : null);
      json.field("problems", problems.toString());
      json.field("heap_per_container_mb", Math.round(bigHeap / (double) bigCount / 1e4) / 100.0);
      json.field("single_container_jvm_xmx16m_heap_mb",
          Math.round((heaps.get(0)[1] - heaps.get(0)[0]) / 1e4) / 100.0);
      json.field("single_container_jvm_total_heap_mb", Math.round(heaps.get(0)[1] / 1e4) / 100.0);
      long threads = 0;
      for (long[] h : heaps) {
        threads += h[2];
      }
      json.field("threads_total", threads);
      json.end();
      System.err.printf("scale %d: converged=%s in %.0f ms, heap/container %.2f MB, threads %d%n", n,
          converged, (last - go) / 1e3, bigHeap / (double) bigCount / 1e6, threads);
    } finally {
      for (Jvm j : jvms) {
        j.close();
      }
    }
  }
}
