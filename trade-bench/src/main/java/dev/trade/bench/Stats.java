package dev.trade.bench;

import java.util.Arrays;

/** Latency samples in nanoseconds and their percentiles. Not thread-safe. */
final class Stats {
  private long[] samples;
  private int size;

  Stats(int expected) {
    samples = new long[Math.max(16, expected)];
  }

  void add(long nanos) {
    if (size == samples.length) {
      samples = Arrays.copyOf(samples, size * 2);
    }
    samples[size++] = nanos;
  }

  void addAll(Stats other) {
    for (int i = 0; i < other.size; i++) {
      add(other.samples[i]);
    }
  }

  int count() {
    return size;
  }

  /** The p-th percentile (0 < p <= 100), nearest-rank, in microseconds. */
  double percentileMicros(double p) {
    if (size == 0) {
      return Double.NaN;
    }
    long[] sorted = Arrays.copyOf(samples, size);
    Arrays.sort(sorted);
    int rank = (int) Math.ceil(p / 100.0 * size);
    return sorted[Math.max(0, Math.min(size - 1, rank - 1))] / 1000.0;
  }

  /** p50, p90, p99, p99.9 and max as a JSON object, in microseconds. */
  void writeTo(Json json) {
    json.begin();
    json.field("count", size);
    json.field("p50_us", round(percentileMicros(50)));
    json.field("p90_us", round(percentileMicros(90)));
    json.field("p99_us", round(percentileMicros(99)));
    json.field("p999_us", round(percentileMicros(99.9)));
    json.field("max_us", round(percentileMicros(100)));
    json.end();
  }

  static double round(double v) {
    return Math.round(v * 10) / 10.0;
  }
}
