package com.example.robot;

import dev.trade.TRADEException;
import java.util.concurrent.CompletableFuture;

/** How a caller sees the gripper's services: a typed proxy implements this interface. */
public interface Arm {
  boolean openGripper(int speed) throws TRADEException;

  CompletableFuture<Boolean> isOpen();
}
