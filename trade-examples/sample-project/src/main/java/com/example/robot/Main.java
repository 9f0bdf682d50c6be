package com.example.robot;

import dev.trade.TRADE;
import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;

/** Registers the gripper and calls it, by lookup and through a typed proxy, in one JVM. */
public final class Main {
  private Main() {}

  public static void main(String[] args) throws Exception {
    TRADE.setDefaultContainer(TRADEContainer.builder().name("sample"));
    TRADE.registerAllServices(new Gripper(), "MyRobot");

    boolean opened = TRADE.getAvailableService(
        new TRADEServiceConstraints().name("openGripper").argTypes(int.class)).call(boolean.class, 3);
    Arm arm = TRADE.proxy(Arm.class, new TRADEServiceConstraints().inGroups("MyRobot"));
    System.out.println("opened " + opened + ", open " + arm.isOpen().get());
  }
}
