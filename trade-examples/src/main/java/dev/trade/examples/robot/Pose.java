package dev.trade.examples.robot;

import java.util.Locale;

/**
 * A position in the robot's workspace, in metres. A record of doubles is an immutable value, so it
 * travels between containers as it is and needs no copying in strict mode.
 */
public record Pose(double x, double y, double z) {
  /** {@code (0.40, 0.10, 0.02)}, for transcripts. */
  @Override
  public String toString() {
    return String.format(Locale.ROOT, "(%.2f, %.2f, %.2f)", x, y, z);
  }
}
