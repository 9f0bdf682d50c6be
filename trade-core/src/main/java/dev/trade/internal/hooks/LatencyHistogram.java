package dev.trade.internal.hooks;

import java.util.concurrent.atomic.AtomicLongArray;

/**
 * Counts durations in buckets of at most 1/8 of their value (8 buckets per power of two, from
 * 1 ns to 2⁶³ ns), so that a percentile is known within 12.5 % with 488 counters and no lock.
 * Recording is one array increment; safe for concurrent use.
 */
final class LatencyHistogram {
  private static final int SUB = 8;
  private final AtomicLongArray counts = new AtomicLongArray(61 * SUB);

  void record(long nanos) {
    counts.incrementAndGet(bucket(Math.max(1, nanos)));
  }

  static int bucket(long nanos) {
    int msb = 63 - Long.numberOfLeadingZeros(nanos);
    if (msb < 3) {
      return (int) nanos; // 1 to 7: exact
    }
    return (msb - 2) * SUB + (int) ((nanos >>> (msb - 3)) & (SUB - 1));
  }

  /** The largest duration bucket {@code b} holds. */
  static long upperBound(int b) {
    if (b < SUB) {
      return b;
    }
    int shift = b / SUB - 1; // msb - 3
    long low = (long) (SUB + b % SUB) << shift;
    return low + (1L << shift) - 1;
  }

  /**
   * The duration below or at which a fraction {@code q} (0 to 1) of the recorded ones lie, as the
   * upper bound of its bucket; 0 when nothing was recorded.
   */
  long percentile(double q) {
    long total = 0;
    long[] snapshot = new long[counts.length()];
    for (int i = 0; i < snapshot.length; i++) {
      snapshot[i] = counts.get(i);
      total += snapshot[i];
    }
    if (total == 0) {
      return 0;
    }
    long rank = Math.max(1, (long) Math.ceil(q * total));
    long seen = 0;
    for (int i = 0; i < snapshot.length; i++) {
      seen += snapshot[i];
      if (seen >= rank) {
        return upperBound(i);
      }
    }
    return upperBound(snapshot.length - 1);
  }
}
