package dev.trade.examples.robot;

import dev.trade.TRADEService;
import java.io.PrintStream;
import java.util.Locale;
import java.util.Objects;

/**
 * A simulated pan/tilt head. Unlike {@link Arm}, its services are annotated in the class itself:
 * both styles register the same way. Safe for concurrent use.
 */
public final class Head {
  private static final double MAX_PAN = 170;
  private static final double MAX_TILT = 60;

  private final PrintStream out;
  private double pan; // Guarded by this.
  private double tilt; // Guarded by this.

  /** A head that prints what it does to {@code out}. */
  public Head(PrintStream out) {
    this.out = Objects.requireNonNull(out, "out == null");
  }

  /**
   * Turns the head to {@code degrees} left (positive) or right (negative) of straight ahead,
   * limited to ±170.
   *
   * @return the pan angle reached
   */
  @TRADEService
  public synchronized double pan(double degrees) {
    pan = Math.max(-MAX_PAN, Math.min(MAX_PAN, degrees));
    out.println(String.format(Locale.ROOT, "panning to %.0f degrees", pan));
    return pan;
  }

  /**
   * Tilts the head to {@code degrees} up (positive) or down (negative), limited to ±60.
   *
   * @return the tilt angle reached
   */
  @TRADEService
  public synchronized double tilt(double degrees) {
    tilt = Math.max(-MAX_TILT, Math.min(MAX_TILT, degrees));
    out.println(String.format(Locale.ROOT, "tilting to %.0f degrees", tilt));
    return tilt;
  }
}
