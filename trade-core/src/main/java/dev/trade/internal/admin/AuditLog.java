package dev.trade.internal.admin;

import java.lang.System.Logger;
import java.lang.System.Logger.Level;

/**
 * Where refused calls are reported: the {@code System.Logger} {@value #NAME}, at WARNING. A caller
 * that guesses secrets must not flood the log, so at most {@code perWindow} refusals are written
 * per window of {@code windowNanos}; the rest are counted, and the first line of the next window
 * says how many were left out. Time is a parameter. Thread-safe: one lock.
 */
final class AuditLog {
  /** The logger's name (docs/security.md). */
  static final String NAME = "dev.trade.audit";

  private final Logger log;
  private final int perWindow;
  private final long windowNanos;
  // Guarded by this.
  private long windowStart;
  private boolean started;
  private int written;
  private long suppressed;

  AuditLog(Logger log, int perWindow, long windowNanos) {
    this.log = log;
    this.perWindow = perWindow;
    this.windowNanos = windowNanos;
  }

  /**
   * Reports a refusal, or counts it if this window has had its lines.
   *
   * @return whether it was written
   */
  boolean refused(String what, long nowNanos) {
    long left;
    synchronized (this) {
      if (!started || nowNanos - windowStart >= windowNanos) {
        started = true;
        windowStart = nowNanos;
        written = 0;
        left = suppressed;
        suppressed = 0;
      } else {
        left = 0;
      }
      if (written >= perWindow) {
        suppressed++;
        return false;
      }
      written++;
    }
    if (left > 0) {
      log.log(Level.WARNING, "{0} more refusals were not logged (at most {1} are logged per {2} s)",
          left, perWindow, windowNanos / 1_000_000_000L);
    }
    log.log(Level.WARNING, "refused: {0}", what);
    return true;
  }
}
