package dev.trade.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

/**
 * How fast this machine runs plain Java just now: the median time of a fixed single-threaded
 * workload (hashing, boxing, sorting, string building: the mix of a container's control thread)
 * after warm-up runs. The CPU of a shared virtual machine is not equally fast at all hours, and
 * the goals stated in absolute time (start → callable, convergence of 100 containers) move with
 * it; this index, taken before each part, lets runs be compared. It is no benchmark of anything.
 */
final class Calibration {
  private static final int WARM_UP = 5;
  private static final int RUNS = 7;

  private Calibration() {}

  /** The median time of {@link #RUNS} runs of the workload after {@link #WARM_UP} untimed, in ms. */
  static double medianMillis() {
    long sink = 0;
    for (int i = 0; i < WARM_UP; i++) {
      sink += work(); // until the JIT has compiled it
    }
    long[] nanos = new long[RUNS];
    for (int i = 0; i < RUNS; i++) {
      long t0 = System.nanoTime();
      sink += work();
      nanos[i] = System.nanoTime() - t0;
    }
    Arrays.sort(nanos);
    if (sink == 42) {
      System.err.print(""); // keeps the work from being optimised away
    }
    return Math.round(nanos[RUNS / 2] / 1e5) / 10.0;
  }

  private static long work() {
    Random random = new Random(1);
    Map<String, Integer> counts = new HashMap<>();
    for (int i = 0; i < 200_000; i++) {
      counts.merge("key-" + random.nextInt(50_000), 1, Integer::sum);
    }
    List<String> keys = new ArrayList<>(counts.keySet());
    Collections.sort(keys);
    long[] numbers = random.longs(300_000).toArray();
    Arrays.sort(numbers);
    StringBuilder text = new StringBuilder();
    for (int i = 0; i < 1000; i++) {
      text.append(keys.get(i)).append(':').append(counts.get(keys.get(i))).append(';');
    }
    return keys.size() + numbers[numbers.length / 2] + text.length();
  }
}
