package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceNotFoundException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Registration validates eagerly and says what is wrong and how to fix it. */
class RegistrationValidationTest {
  private final TRADEContainer trade = TRADEContainer.builder().build();

  @AfterEach
  void close() {
    trade.close();
  }

  static class NonPublicService {
    @TRADEService
    void hidden() {}
  }

  static class StaticService {
    @TRADEService
    public static void shared() {}
  }

  static class Base {
    @TRADEService
    public Number measure() {
      return 1;
    }
  }

  /** Overrides without the annotation and narrows the return type (javac adds a bridge). */
  static class Derived extends Base {
    @Override
    public Integer measure() {
      return 2;
    }

    @TRADEService
    public int add(int a, int b) {
      return a + b;
    }

    @TRADEService
    public long add(long a, long b) {
      return a + b + 1000;
    }
  }

  @Test
  void nonPublicAnnotatedMethodIsRejectedNamingClassAndMethod() {
    TRADERegistrationException e = assertThrows(TRADERegistrationException.class,
        () -> trade.registerAllServices(new NonPublicService()));
    assertEquals("@TRADEService methods must be public; make it public or remove the annotation"
        + "\n    for method org.example.robot.RegistrationValidationTest$NonPublicService.hidden()",
        e.getMessage());
    assertTrue(trade.getAvailableServices().isEmpty(), "nothing registered");
  }

  @Test
  void staticAnnotatedMethodIsRejected() {
    TRADERegistrationException e = assertThrows(TRADERegistrationException.class,
        () -> trade.registerAllServices(new StaticService()));
    assertTrue(e.getMessage().startsWith("@TRADEService methods must not be static"), e.getMessage());
    assertTrue(e.getMessage().endsWith("$StaticService.shared()"), e.getMessage());
  }

  @Test
  void registeringTheSameObjectTwiceIsRejected() throws TRADEException {
    RobotArm arm = new RobotArm();
    trade.registerAllServices(arm, "MyRobot");
    TRADERegistrationException e = assertThrows(TRADERegistrationException.class,
        () -> trade.registerAllServices(arm, "Other"));
    assertTrue(e.getMessage().contains("org.example.robot.RobotArm@"), e.getMessage());
    assertTrue(e.getMessage().contains("already registered; deregister it first"), e.getMessage());
    assertEquals(2, trade.getAvailableServices().size());
    trade.deregister(arm);
    assertEquals(2, trade.registerAllServices(arm, "Other").size());
  }

  @Test
  void deregisteringAnUnknownObjectIsATypedError() {
    assertThrows(TRADEServiceNotFoundException.class, () -> trade.deregister(new RobotArm()));
  }

  @Test
  void overridingWithoutAnnotationStaysAServiceAndBridgesAreNotServices() throws TRADEException {
    Collection<TRADEServiceInfo> infos = trade.registerAllServices(new Derived());
    List<String> strings = new ArrayList<>();
    infos.forEach(i -> strings.add(i.serviceString + ":" + i.serviceReturnTypeName));
    assertEquals(List.of("add(int,int):int", "add(long,long):long", "measure():java.lang.Integer"),
        strings);
    assertEquals(2, trade.getAvailableService(new TRADEServiceConstraints().name("measure"))
        .call(Integer.class));
  }

  @Test
  void overloadsAreSeparateServices() throws TRADEException {
    trade.registerAllServices(new Derived());
    assertEquals(5, trade.getAvailableService(new TRADEServiceConstraints().name("add")
        .argTypes(int.class, int.class)).call(int.class, 2, 3));
    assertEquals(1005L, trade.getAvailableService(new TRADEServiceConstraints().name("add")
        .argTypes(long.class, long.class)).call(long.class, 2L, 3L));
  }

  @Test
  void anonymousAndPackagePrivateProvidersAreCallableFromTheirOwnPackage() throws TRADEException {
    List<String> said = new ArrayList<>();
    trade.registerAllServices(new Object() {
      @TRADEService
      public void say(String text) {
        said.add(text);
      }
    });
    trade.registerAllServices(new BeliefComponent()); // package-private class, public interface
    trade.getAvailableService(new TRADEServiceConstraints().name("say")).call(void.class, "hi");
    assertEquals(List.of("hi"), said);
    assertEquals("beliefs", trade.getAvailableService(new TRADEServiceConstraints().name("getKBName"))
        .call(String.class));
  }

  /** Forgot the annotation. */
  public static class Unannotated {
    public void work() {}
  }

  @Test
  void objectWithoutServicesRegistersNothingAndWarnsNamingTheClassAndTheRule() throws TRADEException {
    Logger registry = Logger.getLogger("dev.trade.registry");
    List<LogRecord> records = new ArrayList<>();
    Handler handler = new Handler() {
      @Override
      public synchronized void publish(LogRecord r) {
        records.add(r);
      }

      @Override
      public void flush() {}

      @Override
      public void close() {}
    };
    registry.addHandler(handler);
    try {
      assertTrue(trade.registerAllServices(new Unannotated(), "g").isEmpty());
    } finally {
      registry.removeHandler(handler);
    }
    synchronized (handler) {
      assertEquals(1, records.size(), "one record");
      assertEquals(Level.WARNING, records.get(0).getLevel());
      assertEquals("registered a " + Unannotated.class.getName() + " in container "
          + trade.getName() + " with no services: a service is a public method annotated"
          + " @TRADEService, on the class or on an interface it implements",
          new SimpleFormatter().formatMessage(records.get(0)));
    }
  }

  @Test
  void closedContainerRefusesWork() {
    trade.close();
    assertThrows(IllegalStateException.class, () -> trade.registerAllServices(new RobotArm()));
    assertThrows(IllegalStateException.class, trade::getAvailableServices);
  }
}
