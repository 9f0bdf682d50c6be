package dev.trade.internal.net.link;

import java.util.HashMap;
import java.util.Map;

/**
 * Which records of a failure that repeats are worth logging: the first at once, then a summary of
 * the repeats at most once per interval, instead of one line per retry (a configured peer that is
 * down is retried every 2 s, for as long as it is down). A failure counts as a repeat while its
 * text is the same; a new text, or a success in between, starts over.
 *
 * <p>Time is a parameter, so that the decisions can be tested on a fake clock. Safe for concurrent
 * use.
 */
final class RepeatedFailures<K> {
  /** What to log for one failure. */
  record Report(boolean first, long repeats, long sinceNanos) {}

  private static final class Run {
    final String text;
    long lastReport;
    long repeats; // since lastReport

    Run(String text, long now) {
      this.text = text;
      this.lastReport = now;
    }
  }

  private final long intervalNanos;
  // Guarded by this.
  private final Map<K, Run> runs = new HashMap<>();

  RepeatedFailures(long intervalNanos) {
    this.intervalNanos = intervalNanos;
  }

  /**
   * Records a failure of {@code key} with {@code text} at {@code now}.
   *
   * @return what to log now: the first failure, or a summary of the {@code repeats} since the last
   *     report {@code sinceNanos} ago; null to log nothing (at INFO) this time
   */
  synchronized Report failed(K key, String text, long now) {
    Run run = runs.get(key);
    if (run == null || !run.text.equals(text)) {
      runs.put(key, new Run(text, now));
      return new Report(true, 0, 0);
    }
    run.repeats++;
    long since = now - run.lastReport;
    if (since < intervalNanos) {
      return null;
    }
    Report r = new Report(false, run.repeats, since);
    run.lastReport = now;
    run.repeats = 0;
    return r;
  }

  /** {@code key} succeeded: its next failure is a first one again. */
  synchronized void succeeded(K key) {
    runs.remove(key);
  }
}
