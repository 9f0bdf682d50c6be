package dev.trade.internal.notify;

import dev.trade.internal.registry.ServiceDescriptor;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One notification while it lives: its request and what became of it (next due time, deliveries,
 * skips, failures). The time logic takes {@code now} as a parameter, so tests drive it with any
 * clock. Safe for concurrent use (state guarded by this).
 */
final class Live {
  /**
   * The most a timed delivery is handed to its delivery thread before it is due, which then waits
   * for its time: a delivery costs that thread's one wake-up at its time, not the timer's and then
   * that thread's. At most half a period, so a delivery is handed over after the one before is due.
   */
  static final long MAX_LEAD_NANOS = 1_000_000;

  /**
   * What the timer does when it wakes for a notification.
   *
   * @param deliver whether to hand a delivery over
   * @param dueNanos the due time of that delivery, which waits for it
   * @param nextNanos when it is due next ({@code -1}: never)
   * @param wakeNanos when the timer wakes for it next ({@code -1}: never)
   */
  record Step(boolean deliver, long dueNanos, long nextNanos, long wakeNanos) {
    static final Step NOTHING = new Step(false, -1, -1, -1);
  }

  final String id;
  final Spec spec;
  // Guarded by this.
  private long nextDue;
  private long fired;
  private long skipped;
  private long failures;
  private String lastError;
  private boolean running;
  private String endReason;
  private Runnable cancelTimer;

  Live(String id, Spec spec) {
    this.id = id;
    this.spec = spec;
    this.nextDue = spec.timing() == null ? -1 : spec.timing().firstNanos();
  }

  /** How long before a due time the timer hands the delivery over. */
  long leadNanos() {
    long period = spec.timing() == null ? 0 : spec.timing().periodNanos();
    return period == 0 ? MAX_LEAD_NANOS : Math.min(period / 2, MAX_LEAD_NANOS);
  }

  /** When the timer first wakes for it: its lead before the first due time. */
  synchronized long firstWake() {
    return nextDue - leadNanos();
  }

  /** The first due time ({@code -1} for joined and left, which follow the registry instead). */
  synchronized long firstDue() {
    return nextDue;
  }

  /**
   * The timer woke for the next due time at {@code now}, up to {@link #leadNanos} before it: hand a
   * delivery over unless one still runs (then this one is skipped and counted, never overlapped;
   * when that is seen before the due time, the timer decides again at the due time, as the one
   * running may end by then). A repeating one is due next a period after this due time (fixed
   * rate), and due times the timer missed altogether (it ran more than a period late) are skipped
   * and counted too.
   */
  synchronized Step due(long now) {
    if (endReason != null) {
      return Step.NOTHING;
    }
    long dueNow = nextDue;
    if (running && now - dueNow < 0) {
      return new Step(false, dueNow, dueNow, dueNow);
    }
    boolean deliver = !running;
    if (deliver) {
      running = true;
    } else {
      skipped++;
    }
    long period = spec.timing().periodNanos();
    if (period == 0) {
      nextDue = -1;
      return new Step(deliver, dueNow, -1, -1);
    }
    nextDue += period;
    if (nextDue - now <= 0) {
      long missed = (now - nextDue) / period + 1;
      nextDue += missed * period;
      skipped += missed;
    }
    return new Step(deliver, dueNow, nextDue, nextDue - leadNanos());
  }

  /** A delivery for a joined or left event starts; false once ended. */
  synchronized boolean startEvent() {
    if (endReason != null) {
      return false;
    }
    running = true;
    return true;
  }

  /**
   * A delivery ended.
   *
   * @param calledBack whether the callback was called and returned
   * @param error what failed (the service or the callback), or null
   * @return whether {@code error} differs from the last one (worth a warning rather than a debug line)
   */
  synchronized boolean finished(boolean calledBack, String error) {
    running = false;
    if (calledBack) {
      fired++;
    }
    if (error == null) {
      return false;
    }
    failures++;
    boolean fresh = !error.equals(lastError);
    lastError = error;
    return fresh;
  }

  /** Whether a delivery runs now (for tests). */
  synchronized boolean running() {
    return running;
  }

  synchronized long skipped() {
    return skipped;
  }

  synchronized long fired() {
    return fired;
  }

  synchronized long failures() {
    return failures;
  }

  synchronized boolean ended() {
    return endReason != null;
  }

  /** Keeps what cancels the pending timer task; cancels it at once if already ended. */
  void timer(Runnable cancel) {
    boolean cancelNow;
    synchronized (this) {
      cancelNow = endReason != null;
      if (!cancelNow) {
        cancelTimer = cancel;
      }
    }
    if (cancelNow) {
      cancel.run();
    }
  }

  /**
   * Ends it, once.
   *
   * @return true the first time: the caller reports the end
   */
  boolean end(String reason) {
    Runnable cancel;
    synchronized (this) {
      if (endReason != null) {
        return false;
      }
      endReason = reason;
      nextDue = -1;
      cancel = cancelTimer;
      cancelTimer = null;
    }
    if (cancel != null) {
      cancel.run();
    }
    return true;
  }

  /** Whether {@code d} is its callback or its service: it cannot live on without it. */
  boolean uses(ServiceDescriptor d) {
    return spec.callback().sameService(d) || (spec.service() != null && spec.service().sameService(d));
  }

  /**
   * What the list of notifications shows of it, at {@code nowNanos} (scheduler time) and
   * {@code nowInstant} (the same moment on the wall clock). Keys as in docs/notifications.md.
   */
  synchronized Map<String, Object> describe(long nowNanos, Instant nowInstant) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("id", id);
    m.put("type", spec.kind().label());
    m.put("requester", spec.requester());
    List<String> services = new ArrayList<>();
    if (spec.service() != null) {
      services.add(where(spec.service()));
    }
    m.put("services", services);
    m.put("callback", where(spec.callback()));
    m.put("nextTime", nextDue < 0 ? null : nowInstant.plusNanos(Math.max(0, nextDue - nowNanos)));
    m.put("timesFired", fired);
    m.put("skipped", skipped);
    m.put("failures", failures);
    m.put("lastError", lastError);
    if (endReason != null) {
      m.put("endReason", endReason);
    }
    return m;
  }

  static String where(ServiceDescriptor d) {
    return d.signature() + " @ " + d.containerName();
  }
}
