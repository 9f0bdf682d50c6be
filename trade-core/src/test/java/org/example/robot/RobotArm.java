package org.example.robot;

import dev.trade.TRADEService;
import java.util.ArrayList;
import java.util.List;

/** The TRADE paper's example provider, annotated on the class itself. */
public class RobotArm {
  final List<Integer> speeds = new ArrayList<>();

  // open the gripper at given speed
  @TRADEService
  public boolean openGripper(int speed) {
    speeds.add(speed);
    return speed > 0;
  }

  @TRADEService
  public void closeGripper() {
    speeds.add(0);
  }

  /** Not a service: no annotation. */
  public int notAService() {
    return 1;
  }
}
