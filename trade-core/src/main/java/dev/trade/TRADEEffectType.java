package dev.trade;

import java.util.Locale;

/**
 * When the effect a {@link TRADEEffect} describes holds after a call of its service.
 *
 * <p>TRADE itself gives these no behaviour: they are metadata for planners and action databases
 * that read a service's annotations (through {@link TRADEServiceInfo#getAnnotations()}, also for
 * services of other JVMs).
 */
public enum TRADEEffectType {
  /** Whatever the outcome of the call. */
  ALWAYS,
  /** When the call succeeds. */
  SUCCESS,
  /** When the call fails. */
  FAILURE,
  /** When the call is not performed at all (refused or cancelled before it ran). */
  NONPERF;

  /**
   * The constant named {@code name}, ignoring case and surrounding blanks: {@code "success"} gives
   * {@link #SUCCESS}.
   *
   * @param name a constant's name
   * @return the constant
   * @throws IllegalArgumentException if {@code name} is null or names no constant; the message lists
   *     the accepted names
   */
  public static TRADEEffectType fromString(String name) {
    if (name != null) {
      String n = name.strip().toUpperCase(Locale.ROOT);
      for (TRADEEffectType t : values()) {
        if (t.name().equals(n)) {
          return t;
        }
      }
    }
    throw new IllegalArgumentException("TRADEEffectType.fromString(" + (name == null ? "null" : "\""
        + name + "\"") + "): expected one of always, success, failure, nonperf (any case)");
  }
}
