package dev.trade.internal.net.link;

/**
 * One link's round-trip time, measured by the heartbeat: a PING that asks for an echo carries a
 * token (the time it was sent), the peer sends the token back in a PING at once, and the time
 * between is one sample. The estimate is the mean of the first 8 samples, then smoothed as TCP
 * smooths its own (RFC 6298: 7/8 of the last estimate plus 1/8 of the new sample), so that one
 * late echo moves it little. Not TCP's first sample alone: the first probe leaves as the link comes
 * up, often in a JVM still starting, and an estimate that began there took many seconds to
 * forget it (0.5 s measured 6 s after a start on a loaded machine). One probe is
 * outstanding at a time; an echo of any other token (an old probe's, or a forged one) is ignored.
 * Times are nanoTime readings passed in. Safe for concurrent use.
 */
final class RoundTrip {
  /** What {@link #nanos} says before the first echo. */
  static final long UNKNOWN = -1;

  // Guarded by this.
  private long lastProbe;
  private long outstanding;
  private boolean waiting;
  private long smoothed = UNKNOWN;
  private int samples;
  private long sum; // of the first samples

  /** @param created when the link came up: the first probe is due from then on */
  RoundTrip(long created) {
    this.lastProbe = created;
  }

  /**
   * Whether a probe is due at {@code now}: the last one went out {@code every} nanoseconds ago or
   * more (an echo that never came does not hold probing up: an older peer ignores probes).
   */
  synchronized boolean due(long now, long every) {
    return now - lastProbe >= every;
  }

  /** A probe leaves at {@code now}; returns its token. */
  synchronized long sent(long now) {
    lastProbe = now;
    outstanding = now;
    waiting = true;
    return now;
  }

  /**
   * The peer echoed {@code token} at {@code now}.
   *
   * @return whether it answered the outstanding probe (and was counted)
   */
  synchronized boolean echoed(long token, long now) {
    if (!waiting || token != outstanding || now - token < 0) {
      return false;
    }
    waiting = false;
    long sample = now - token;
    if (samples < 8) {
      sum += sample;
      smoothed = sum / ++samples;
    } else {
      smoothed = smoothed - smoothed / 8 + sample / 8;
    }
    return true;
  }

  /** The smoothed round-trip time in nanoseconds, or {@link #UNKNOWN} before the first echo. */
  synchronized long nanos() {
    return smoothed;
  }
}
