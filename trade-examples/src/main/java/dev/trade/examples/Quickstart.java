package dev.trade.examples;

import dev.trade.TRADE;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.Collection;

/** The README's quickstart: the TRADE paper's robot arm, registered, found and called. */
public final class Quickstart {
  /** A robot arm component; any object with {@code @TRADEService} methods can be registered. */
  public static class RobotArm {
    @TRADEService
    public boolean openGripper(int speed) {
      System.out.println("  [arm] opening gripper at speed " + speed);
      return true;
    }

    @TRADEService
    public void closeGripper() {
      System.out.println("  [arm] closing gripper");
    }
  }

  private Quickstart() {}

  public static void main(String[] args) throws TRADEException {
    TRADE.register(new RobotArm(), "MyRobot");

    Collection<TRADEServiceInfo> myRobotServices =
        TRADE.getAvailableServices(new TRADEServiceConstraints().inGroups("MyRobot"));
    System.out.println("services in MyRobot:");
    for (TRADEServiceInfo s : myRobotServices) {
      System.out.println("  " + s);
    }
    for (TRADEServiceInfo s : myRobotServices) {
      if (s.serviceString.equals("openGripper(int)")) {
        boolean opened = s.call(boolean.class, 3);
        System.out.println("openGripper(3) returned " + opened);
      }
    }
    TRADE.getAvailableService(new TRADEServiceConstraints().name("closeGripper").argTypes())
        .call(void.class);
  }
}
