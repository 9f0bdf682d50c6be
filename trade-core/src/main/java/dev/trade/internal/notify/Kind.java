package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import java.util.Locale;

/** The notification types and what each needs and delivers; see docs/notifications.md. */
enum Kind {
  /** A service matching the constraints joined; delivers its info. */
  JOINED,
  /** A service matching the constraints left; delivers its info. */
  LEFT,
  /** Calls {@code services[0]} now, without blocking the requester; delivers its result. */
  ONCE,
  /** After a delay: calls back, or calls {@code services[0]} and delivers its result. */
  AFTER,
  /** At an instant: as {@link #AFTER}. */
  AT,
  /** Every period, at a fixed rate: calls back, or streams {@code services[0]}'s results. */
  EVERY,
  /** At the scheduled time, calls back only if the condition {@code services[0]} is true. */
  IF,
  /** Polls the condition {@code services[0]} every period; calls back once, the first time it is true. */
  WHEN;

  static final String SUPPORTED = "joined, left, once, after, at, every, if, when";

  /** The type's name as requests spell it. */
  String label() {
    return name().toLowerCase(Locale.ROOT);
  }

  /** Whether the type needs {@code services[0]} (the service called, or the condition). */
  boolean needsService() {
    return this == ONCE || this == IF || this == WHEN;
  }

  /** Whether the type takes a service at all. */
  boolean takesService() {
    return this != JOINED && this != LEFT;
  }

  /** Whether {@code services[0]} is a condition (returns boolean) rather than a value. */
  boolean isCondition() {
    return this == IF || this == WHEN;
  }

  /**
   * @throws TRADEBadArgumentsException naming the supported types
   */
  static Kind parse(String type) throws TRADEBadArgumentsException {
    if (type != null) {
      for (Kind k : values()) {
        if (k.label().equals(type.toLowerCase(Locale.ROOT))) {
          return k;
        }
      }
    }
    throw new TRADEBadArgumentsException("Unknown notification type '" + type + "'; supported: "
        + SUPPORTED);
  }
}
