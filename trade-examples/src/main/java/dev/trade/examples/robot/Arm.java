package dev.trade.examples.robot;

import dev.trade.TRADEService;

/**
 * A robot arm with a gripper. The services are declared here, on the interface (the DIARC style):
 * an implementing class only needs {@code @Override}, and every implementation registers the same
 * services.
 */
public interface Arm {
  /**
   * Opens the gripper.
   *
   * @param speed 1..100
   * @return whether the gripper is open
   * @throws IllegalArgumentException if {@code speed} is out of range (callers see it as the cause
   *     of a {@code TRADEInvocationException})
   */
  @TRADEService
  boolean openGripper(int speed);

  /** Closes the gripper on whatever is between its fingers. */
  @TRADEService
  void closeGripper();

  /**
   * Moves the gripper to {@code target}.
   *
   * @return the pose reached
   */
  @TRADEService
  Pose moveTo(Pose target);
}
