package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import java.time.Duration;
import java.time.Instant;

/**
 * When a timed notification is first due and how often after that: an immutable value computed
 * from the request's time argument and the time of the request.
 *
 * @param firstNanos the first due time, on the scheduler's {@code nanoTime} scale
 * @param periodNanos the period of a repeating type; 0 for one that is due once
 */
record Timing(long firstNanos, long periodNanos) {
  /** The shortest period of {@code every} and {@code when}: shorter ones are refused. */
  static final Duration MIN_PERIOD = Duration.ofMillis(1);

  /**
   * The timing of {@code kind} for its time argument {@code time}, requested at {@code nowNanos}
   * (scheduler time) and {@code nowInstant} (wall-clock time of the same moment).
   *
   * @throws TRADEBadArgumentsException an argument of the wrong kind, negative, or a period that is
   *     not positive or below {@link #MIN_PERIOD}
   */
  static Timing of(Kind kind, Object time, long nowNanos, Instant nowInstant)
      throws TRADEBadArgumentsException {
    switch (kind) {
      case ONCE:
        return new Timing(nowNanos, 0);
      case AFTER:
        return new Timing(nowNanos + delay(kind, time), 0);
      case AT:
        return new Timing(nowNanos + until(kind, time, nowInstant), 0);
      case IF:
        return new Timing(nowNanos + (time instanceof Instant ? until(kind, time, nowInstant)
            : delay(kind, time)), 0);
      case EVERY:
      case WHEN:
        long period = period(kind, time);
        // The first delivery is one period from now (a poll at once would race the request's
        // own set-up of the state it watches).
        return new Timing(nowNanos + period, period);
      default:
        throw new IllegalArgumentException(kind + " is not timed");
    }
  }

  private static long delay(Kind kind, Object time) throws TRADEBadArgumentsException {
    long nanos = nanos(kind, time, "a delay: long milliseconds or a Duration");
    if (nanos < 0) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' needs a delay of zero or more; got "
          + time);
    }
    return nanos;
  }

  private static long until(Kind kind, Object time, Instant now) throws TRADEBadArgumentsException {
    Instant at;
    if (time instanceof Instant) {
      at = (Instant) time;
    } else if (time instanceof Long || time instanceof Integer) {
      at = Instant.ofEpochMilli(((Number) time).longValue());
    } else {
      throw wrongKind(kind, time, "an Instant, or long milliseconds since the epoch");
    }
    return saturatedNanos(Duration.between(now, at).isNegative() ? Duration.ZERO
        : Duration.between(now, at));
  }

  private static long period(Kind kind, Object time) throws TRADEBadArgumentsException {
    long nanos = nanos(kind, time, "a period: long milliseconds or a Duration");
    if (nanos < MIN_PERIOD.toNanos()) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' needs a period of at least "
          + MIN_PERIOD.toMillis() + " ms; got " + (time instanceof Duration ? time : time + " ms"));
    }
    return nanos;
  }

  private static long nanos(Kind kind, Object time, String expected) throws TRADEBadArgumentsException {
    if (time instanceof Long || time instanceof Integer) {
      long ms = ((Number) time).longValue();
      return Math.abs(ms) > Long.MAX_VALUE / 4_000_000 ? Long.signum(ms) * (Long.MAX_VALUE / 4)
          : ms * 1_000_000;
    }
    if (time instanceof Duration) {
      return saturatedNanos((Duration) time);
    }
    throw wrongKind(kind, time, expected);
  }

  private static long saturatedNanos(Duration d) {
    try {
      return d.toNanos();
    } catch (ArithmeticException tooLong) {
      return d.isNegative() ? -Long.MAX_VALUE / 4 : Long.MAX_VALUE / 4; // centuries
    }
  }

  private static TRADEBadArgumentsException wrongKind(Kind kind, Object time, String expected) {
    return new TRADEBadArgumentsException("'" + kind.label() + "' needs " + expected + "; got "
        + (time == null ? "null" : time.getClass().getName() + " " + time));
  }
}
