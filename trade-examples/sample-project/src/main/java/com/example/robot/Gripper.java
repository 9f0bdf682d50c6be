package com.example.robot;

import dev.trade.TRADEService;

/** A component that provides services: its annotated public methods. */
public class Gripper {
  private volatile boolean open;

  @TRADEService
  public boolean openGripper(int speed) {
    open = speed > 0;
    return open;
  }

  @TRADEService
  public boolean isOpen() {
    return open;
  }
}
