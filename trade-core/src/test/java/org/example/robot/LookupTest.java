package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceNotFoundException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Constraint matching (and, or, not, host, local) and the deterministic preference. */
class LookupTest {
  private final TRADEContainer trade = TRADEContainer.builder().name("lookup").build();

  @AfterEach
  void close() {
    trade.close();
  }

  public static class Camera {
    final String id;

    Camera(String id) {
      this.id = id;
    }

    @TRADEService
    public String checkFor(String objectType) {
      return id + ":" + objectType;
    }
  }

  @Test
  void preferenceIsRegistrationOrderAmongLocalServicesNeverRandom() throws TRADEException {
    for (int i = 0; i < 20; i++) {
      trade.registerAllServices(new Camera("cam" + i), "MyRobot");
    }
    TRADEServiceConstraints c = new TRADEServiceConstraints().name("checkFor");
    for (int i = 0; i < 50; i++) {
      assertEquals("cam0:cup", trade.getAvailableService(c).call(String.class, "cup"));
    }
    List<String> order = new ArrayList<>();
    for (TRADEServiceInfo s : trade.getAvailableServices(c)) {
      order.add(s.call(String.class, "x"));
    }
    for (int i = 0; i < 20; i++) {
      assertEquals("cam" + i + ":x", order.get(i));
    }
  }

  @Test
  void notFoundNamesTheConstraints() {
    TRADEServiceNotFoundException e = assertThrows(TRADEServiceNotFoundException.class,
        () -> trade.getAvailableService(new TRADEServiceConstraints().name("fly")
            .argTypes(int.class).inGroups("MyRobot")));
    assertEquals("No service matches TRADEServiceConstraints{name=fly, argTypes=(int), "
        + "inGroups=[MyRobot]}", e.getMessage());
  }

  @Test
  void notFoundSuggestsTheNearestNamesWithTheirSignatures() throws TRADEException {
    trade.registerAllServices(new RobotArm(), "MyRobot");
    TRADEServiceNotFoundException misspelled = assertThrows(TRADEServiceNotFoundException.class,
        () -> trade.getAvailableService(new TRADEServiceConstraints().name("opnGripper")));
    assertEquals("No service matches TRADEServiceConstraints{name=opnGripper}; did you mean"
        + " boolean openGripper(int) [MyRobot] @ lookup?", misspelled.getMessage());

    TRADEServiceNotFoundException wrongArguments = assertThrows(TRADEServiceNotFoundException.class,
        () -> trade.getAvailableService(new TRADEServiceConstraints().name("openGripper")
            .argTypes(String.class)));
    assertEquals("No service matches TRADEServiceConstraints{name=openGripper,"
        + " argTypes=(java.lang.String)}; services named openGripper: boolean openGripper(int)"
        + " [MyRobot] @ lookup", wrongArguments.getMessage());

    TRADEServiceNotFoundException farOff = assertThrows(TRADEServiceNotFoundException.class,
        () -> trade.getAvailableService(new TRADEServiceConstraints().name("fly")));
    assertEquals("No service matches TRADEServiceConstraints{name=fly}", farOff.getMessage());
  }

  @Test
  void orAndNotFormADisjunctiveNormalForm() throws TRADEException {
    trade.registerAllServices(new RobotArm(), "Sim");
    RobotArm real = new RobotArm();
    trade.registerAllServices(real, "MyRobot");
    trade.registerAllServices(new Camera("c"), "MyRobot");
    TRADEServiceConstraints c = new TRADEServiceConstraints().name("openGripper")
        .or(new TRADEServiceConstraints().name("closeGripper"))
        .not(new TRADEServiceConstraints().inGroups("Sim"));
    List<String> found = new ArrayList<>();
    trade.getAvailableServices(c).forEach(s -> found.add(s.serviceName + s.getGroups()));
    // the negation guards its own conjunction; the alternative stands on its own
    assertEquals(List.of("closeGripper[Sim]", "closeGripper[MyRobot]", "openGripper[MyRobot]"), found);

    TRADEServiceConstraints neither = new TRADEServiceConstraints().inGroups("MyRobot")
        .not(new TRADEServiceConstraints().name("checkFor"))
        .not(new TRADEServiceConstraints().name("closeGripper"));
    assertEquals("openGripper(int)", trade.getAvailableService(neither).serviceString);
    assertEquals(1, trade.getAvailableServices(neither).size());
  }

  @Test
  void alternativesAreCopiedWhenAdded() throws TRADEException {
    trade.registerAllServices(new RobotArm());
    TRADEServiceConstraints alt = new TRADEServiceConstraints().name("closeGripper");
    TRADEServiceConstraints c = new TRADEServiceConstraints().name("nothing").or(alt);
    alt.name("openGripper");
    assertEquals("closeGripper()", trade.getAvailableService(c).serviceString);
  }

  @Test
  void hostAndLocalConstraints() throws TRADEException {
    trade.registerAllServices(new RobotArm());
    TRADEServiceInfo s = trade.getAvailableService(new TRADEServiceConstraints().local()
        .host(trade.getHost()).name("closeGripper"));
    assertTrue(s.isLocal());
    assertEquals(trade.getId(), s.getContainerId());
    assertEquals("lookup", s.getContainerName());
    assertTrue(trade.getAvailableServices(new TRADEServiceConstraints().host("elsewhere")).isEmpty());
  }

  @Test
  void nullConstraintsMatchEverything() throws TRADEException {
    trade.registerAllServices(new RobotArm());
    assertEquals(2, trade.getAvailableServices((TRADEServiceConstraints) null).size());
    assertSame(TRADEServiceInfo.class, trade.getAvailableService(null).getClass());
  }
}
