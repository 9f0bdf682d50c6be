package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

class TwoContainersTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }

    @TRADEService
    public List<String> echo(List<String> words) {
      return words;
    }

    @TRADEService
    public void jam() {
      throw new IllegalStateException("jammed");
    }
  }

  @RegisterExtension final Hubs net = new Hubs();
  private final TRADEContainer hub = net.hub("hub");
  private final TRADEContainer spoke = net.spoke("spoke", hub);

  private static TRADEServiceInfo await(TRADEContainer c, TRADEServiceConstraints constraints) {
    Await.until(WAIT, () -> !c.getAvailableServices(constraints).isEmpty(), constraints.toString());
    try {
      return c.getAvailableService(constraints);
    } catch (TRADEException e) {
      throw new AssertionError(e);
    }
  }

  @Test
  void servicesOfOneContainerAreCallableFromTheOther() throws TRADEException {
    spoke.registerAllServices(new Arm(), "MyRobot");
    TRADEServiceInfo open = await(hub, new TRADEServiceConstraints().inGroups("MyRobot").name("openGripper"));
    assertFalse(open.isLocal());
    assertEquals("spoke", open.getContainerName());
    assertTrue(open.call(boolean.class, 3));
    assertEquals(List.of("a", "b"), await(hub, new TRADEServiceConstraints().name("echo"))
        .call(List.class, List.of("a", "b")));

    hub.registerAllServices(new Arm(), "Hub");
    TRADEServiceInfo back = await(spoke, new TRADEServiceConstraints().inGroups("Hub").name("openGripper"));
    assertFalse(back.call(boolean.class, 0));
  }

  @Test
  void remoteExceptionIsRebuiltAsItsOwnClass() throws TRADEException {
    spoke.registerAllServices(new Arm());
    TRADEServiceInfo jam = await(hub, new TRADEServiceConstraints().name("jam"));
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class, () -> jam.call(void.class));
    assertInstanceOf(IllegalStateException.class, e.getCause());
    assertEquals("jammed", e.getCause().getMessage());
  }

  @Test
  void deregistrationReachesTheOtherContainerAndOldHandlesFailTyped() throws TRADEException {
    Arm arm = new Arm();
    spoke.registerAllServices(arm);
    TRADEServiceInfo open = await(hub, new TRADEServiceConstraints().name("openGripper"));
    spoke.deregister(arm);
    Await.until(WAIT, () -> hub.getAvailableServices(new TRADEServiceConstraints().name("openGripper"))
        .isEmpty(), "deregistration to replicate");
    TRADEServiceUnavailableException e =
        assertThrows(TRADEServiceUnavailableException.class, () -> open.call(boolean.class, 1));
    assertTrue(e.getMessage().startsWith("Service not available any longer"), e.getMessage());
  }
}
