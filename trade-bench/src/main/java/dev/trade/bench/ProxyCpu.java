package dev.trade.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;

/**
 * What a typed proxy adds to a local call, judged within one run: the {@link ProxyCallBench} calls
 * (direct {@code TRADEServiceInfo.call} and the same service through the proxy) timed by this
 * thread's CPU time, in interleaved blocks whose order alternates (call then proxy, proxy then
 * call), so that a machine that slows down or speeds up weighs on both alike. Each pair of blocks
 * gives one difference; the figure is their median, with the quartiles as its spread. CPU time
 * counts only the work, not the time the thread waited for a core on a busy machine.
 */
final class ProxyCpu {
  static final int PAIRS = 25;

  private ProxyCpu() {}

  static void run(Json json) throws Throwable {
    ProxyCallBench b = new ProxyCallBench();
    b.setUp();
    LocalCpu.Op call = () -> b.call() ? 1 : 0;
    LocalCpu.Op proxy = () -> b.proxy() ? 1 : 0;
    int calls = Boolean.getBoolean("bench.quick") ? 100_000 : 1_000_000;
    long sink = 0;
    for (int w = 0; w < 5; w++) { // both paths compiled before anything counts
      sink += block(call, calls) + block(proxy, calls);
    }
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    double[] direct = new double[PAIRS];
    double[] proxied = new double[PAIRS];
    double[] difference = new double[PAIRS];
    for (int p = 0; p < PAIRS; p++) {
      boolean callFirst = p % 2 == 0;
      for (int half = 0; half < 2; half++) {
        boolean isCall = callFirst == (half == 0);
        long t0 = threads.getCurrentThreadCpuTime();
        sink += block(isCall ? call : proxy, calls);
        double ns = (threads.getCurrentThreadCpuTime() - t0) / (double) calls;
        if (isCall) {
          direct[p] = ns;
        } else {
          proxied[p] = ns;
        }
      }
      difference[p] = proxied[p] - direct[p];
    }
    Arrays.sort(difference);
    json.key("proxy_cpu_ns_per_call").begin();
    json.field("call", round(median(direct)));
    json.field("proxy", round(median(proxied)));
    json.field("difference_median", round(difference[PAIRS / 2]));
    json.field("difference_q1", round(difference[PAIRS / 4]));
    json.field("difference_q3", round(difference[PAIRS * 3 / 4]));
    json.field("pairs", PAIRS);
    json.field("calls_per_block", calls);
    json.end();
    json.field("sink", sink % 2);
    System.err.printf("proxy cpu: call %.1f ns, proxy %.1f ns; proxy - call median %+.1f ns"
        + " (quartiles %+.1f .. %+.1f) over %d interleaved pairs of %,d calls%n",
        median(direct), median(proxied), difference[PAIRS / 2], difference[PAIRS / 4],
        difference[PAIRS * 3 / 4], PAIRS, calls);
    b.tearDown();
  }

  private static long block(LocalCpu.Op op, int calls) throws Throwable {
    long sink = 0;
    for (int i = 0; i < calls; i++) {
      sink += op.run();
    }
    return sink;
  }

  private static double median(double[] values) {
    double[] sorted = values.clone();
    Arrays.sort(sorted);
    return sorted[sorted.length / 2];
  }

  private static double round(double v) {
    return Math.round(v * 10) / 10.0;
  }
}
