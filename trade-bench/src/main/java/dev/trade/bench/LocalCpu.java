package dev.trade.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The {@link LocalCallBench} calls again, timed by this thread's CPU time instead of wall time.
 * On a shared machine with more runnable threads than cores, JMH's wall-clock average also counts
 * the time the benchmark thread waited for a core, which inflates every figure by the load factor;
 * CPU time counts only the work. Median of 7 runs of 2 million calls each, after warm-up.
 */
final class LocalCpu {
  private LocalCpu() {}

  interface Op {
    int run() throws Throwable;
  }

  static void run(Json json) throws Throwable {
    LocalCallBench b = new LocalCallBench();
    b.setUp();
    Map<String, Op> ops = new LinkedHashMap<>();
    ops.put("direct", () -> b.direct() ? 1 : 0);
    ops.put("methodHandle", () -> b.methodHandle() ? 1 : 0);
    ops.put("tradeNonStrict", () -> b.tradeNonStrict() ? 1 : 0);
    ops.put("tradeStrict", () -> b.tradeStrict() ? 1 : 0);
    ops.put("tradeNonStrict1KB", b::tradeNonStrict1KB);
    ops.put("tradeStrict1KB", b::tradeStrict1KB);
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    int calls = Boolean.getBoolean("bench.quick") ? 200_000 : 2_000_000;
    long sink = 0;
    for (Op op : ops.values()) { // warm every path first, so that later ones do not deoptimise earlier
      for (int i = 0; i < calls; i++) {
        sink += op.run();
      }
    }
    json.key("cpu_ns_per_call").begin();
    for (Map.Entry<String, Op> e : ops.entrySet()) {
      double[] runs = new double[7];
      for (int r = 0; r < runs.length; r++) {
        long t0 = threads.getCurrentThreadCpuTime();
        for (int i = 0; i < calls; i++) {
          sink += e.getValue().run();
        }
        runs[r] = (threads.getCurrentThreadCpuTime() - t0) / (double) calls;
      }
      Arrays.sort(runs);
      json.field(e.getKey(), Math.round(runs[runs.length / 2] * 10) / 10.0);
      System.err.printf("local cpu %-18s %7.1f ns/call%n", e.getKey(), runs[runs.length / 2]);
    }
    json.end();
    json.field("sink", sink % 2);
    b.tearDown();
  }
}
