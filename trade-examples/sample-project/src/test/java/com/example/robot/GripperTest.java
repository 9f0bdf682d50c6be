package com.example.robot;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class GripperTest {
  @Test
  void theProxyCallsTheGripper() throws Exception {
    try (TRADEContainer c = TRADEContainer.builder().name("test").build()) {
      c.registerAllServices(new Gripper(), "MyRobot");
      Arm arm = c.proxy(Arm.class);
      assertFalse(arm.isOpen().get(10, TimeUnit.SECONDS));
      assertTrue(arm.openGripper(3));
      assertTrue(arm.isOpen().get(10, TimeUnit.SECONDS));
    }
  }
}
