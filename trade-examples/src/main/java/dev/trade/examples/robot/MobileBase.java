package dev.trade.examples.robot;

import java.io.PrintStream;
import java.util.Objects;
import java.util.Set;

/** A simulated {@link Navigation} that knows a few places. Safe for concurrent use. */
public final class MobileBase implements Navigation {
  private static final Set<String> PLACES = Set.of("kitchen", "table", "dock");

  private final PrintStream out;
  private String location = "dock"; // Guarded by this.

  /** A base that prints where it drives to {@code out}. */
  public MobileBase(PrintStream out) {
    this.out = Objects.requireNonNull(out, "out == null");
  }

  @Override
  public synchronized boolean goTo(String location) {
    if (!PLACES.contains(location)) {
      throw new IllegalArgumentException("unknown place '" + location + "'; known: " + PLACES);
    }
    out.println("driving from the " + this.location + " to the " + location);
    this.location = location;
    return true;
  }
}
