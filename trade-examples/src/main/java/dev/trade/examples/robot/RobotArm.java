package dev.trade.examples.robot;

import java.io.PrintStream;
import java.util.Objects;

/**
 * A simulated {@link Arm}: it prints what it does and always succeeds. Safe for concurrent use
 * (calls from several containers may arrive at once).
 */
public final class RobotArm implements Arm {
  private final PrintStream out;
  private Pose pose = new Pose(0, 0, 0.3); // Guarded by this.

  /** An arm that prints what it does to {@code out}. */
  public RobotArm(PrintStream out) {
    this.out = Objects.requireNonNull(out, "out == null");
  }

  @Override
  public boolean openGripper(int speed) {
    if (speed < 1 || speed > 100) {
      throw new IllegalArgumentException("speed must be 1..100: " + speed);
    }
    out.println("opening gripper at speed " + speed);
    return true;
  }

  @Override
  public void closeGripper() {
    out.println("closing gripper");
  }

  @Override
  public synchronized Pose moveTo(Pose target) {
    Objects.requireNonNull(target, "target == null");
    out.println("moving from " + pose + " to " + target);
    pose = target;
    return pose;
  }
}
