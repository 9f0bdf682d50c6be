package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.Collection;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The snippets of the TRADE paper, as written there (modulo the container instance). */
class PaperSnippetsTest {
  private final TRADEContainer trade = TRADEContainer.builder().name("paper").build();

  @AfterEach
  void close() {
    trade.close();
  }

  @Test
  void registerWithoutGroupMakesServicesAvailableSystemWide() throws TRADEException {
    RobotArm arm = new RobotArm();
    trade.register(arm, (String) null);
    TRADEServiceInfo s = trade.getAvailableService(new TRADEServiceConstraints().name("openGripper"));
    assertTrue(s.getGroups().isEmpty());
    assertEquals(List.of(), List.copyOf(s.getGroups()));
  }

  @Test
  void findByGroupCompareServiceStringAndCallWithVoidClass() throws TRADEException {
    RobotArm arm = new RobotArm();
    trade.register(arm, "MyRobot");
    trade.register(new RobotArm(), "OtherRobot");

    Collection<TRADEServiceInfo> myRobotServices =
        trade.getAvailableServices(new TRADEServiceConstraints().inGroups("MyRobot"));
    assertEquals(2, myRobotServices.size());
    TRADEServiceInfo myGripper = null;
    for (TRADEServiceInfo s : myRobotServices) {
      if (s.serviceString.equals("openGripper(int)")) {
        myGripper = s;
        break;
      }
    }
    assertNotNull(myGripper);
    assertNull(myGripper.call(void.class, 3));
    assertEquals(List.of(3), arm.speeds);
  }

  @Test
  void booleanClassReturnsAValueUsableAsPrimitive() throws TRADEException {
    trade.register(new RobotArm(), "MyRobot");
    boolean opened = trade.getAvailableService(
        new TRADEServiceConstraints().name("openGripper").argTypes(int.class)).call(boolean.class, 5);
    assertTrue(opened);
  }

  @Test
  void localGroupLookupAndCall() throws TRADEException {
    RobotArm arm = new RobotArm();
    trade.register(arm, "MyRobot");
    trade.getAvailableService(new TRADEServiceConstraints().inGroups("MyRobot").name("closeGripper")
        .local()).call(void.class);
    assertEquals(List.of(0), arm.speeds);
  }
}
