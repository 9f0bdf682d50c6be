package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Arguments are checked before invoking; results and failures come back typed. */
class CallSemanticsTest {
  private final TRADEContainer trade = TRADEContainer.builder().build();
  private final Motor motor = new Motor();

  public static class Motor {
    int invocations;
    final IllegalStateException failure = new IllegalStateException("jammed");

    @TRADEService
    public long move(int speed, long distance) {
      invocations++;
      return speed * distance;
    }

    @TRADEService
    public double scale(double factor) {
      invocations++;
      return factor * 2;
    }

    @TRADEService
    public void fail() {
      throw failure;
    }

    @TRADEService
    public Object anything(String kind) {
      return kind.equals("list") ? List.of(1) : kind;
    }

    @TRADEService
    public String[] echo(String[] words) {
      return words;
    }
  }

  @BeforeEach
  void register() throws TRADEException {
    trade.registerAllServices(motor);
  }

  @AfterEach
  void close() {
    trade.close();
  }

  private TRADEServiceInfo service(String name) throws TRADEException {
    return trade.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  @Test
  void wrongArgumentTypeNamesIndexNameAndExpectedTypeAndInvokesNothing() throws TRADEException {
    TRADEBadArgumentsException e = assertThrows(TRADEBadArgumentsException.class,
        () -> service("move").call(long.class, 3, "far"));
    assertEquals("Argument 1 ('distance', expected long) is a java.lang.String"
        + "\n    for service move(int,long)", e.getMessage());
    assertEquals(0, motor.invocations);
  }

  @Test
  void nullForAPrimitiveIsRejected() throws TRADEException {
    TRADEBadArgumentsException e = assertThrows(TRADEBadArgumentsException.class,
        () -> service("move").call(long.class, null, 2L));
    assertEquals("Argument 0 ('speed', expected int) is null, but the parameter is primitive"
        + "\n    for service move(int,long)", e.getMessage());
  }

  @Test
  void wrongArgumentCountListsTheParameters() throws TRADEException {
    TRADEBadArgumentsException e = assertThrows(TRADEBadArgumentsException.class,
        () -> service("move").call(long.class, 3));
    assertEquals("Service move(int,long) takes 2 arguments (int speed, long distance) but got 1",
        e.getMessage());
  }

  @Test
  void primitiveWideningAppliesAsInReflection() throws TRADEException {
    assertEquals(12L, service("move").call(long.class, (short) 3, 4));
    assertEquals(3.0, service("scale").call(double.class, 1.5f));
    assertEquals(4.0, service("scale").call(double.class, 2));
    // char widens to int, long, float and double, as in Java (it was refused for int).
    assertEquals(97L * 98L, service("move").call(long.class, 'a', 'b'));
    assertEquals(97.0 * 2, service("scale").call(double.class, 'a'));
    assertThrows(TRADEBadArgumentsException.class, () -> service("move").call(long.class, 3L, 4L));
  }

  @Test
  void serviceExceptionIsTheCauseOfAnInvocationException() throws TRADEException {
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class,
        () -> service("fail").call(void.class));
    assertSame(motor.failure, e.getCause());
  }

  @Test
  void returnTypesConvertOrFailTyped() throws TRADEException {
    assertNull(service("move").call(void.class, 1, 2L));
    assertEquals(2L, service("move").call(Object.class, 1, 2L));
    assertEquals(2L, service("move").call(Long.class, 1, 2L));
    assertEquals(2L, (long) service("move").call(Number.class, 1, 2L));
    assertEquals("x", service("anything").call(String.class, "x"));
    TRADEBadArgumentsException wrongValue = assertThrows(TRADEBadArgumentsException.class,
        () -> service("anything").call(String.class, "list"));
    assertEquals("Service anything(java.lang.String) returned a "
        + List.of(1).getClass().getTypeName() + ", which is not a java.lang.String",
        wrongValue.getMessage());
    int before = motor.invocations;
    TRADEBadArgumentsException wrongType = assertThrows(TRADEBadArgumentsException.class,
        () -> service("move").call(String.class, 1, 2L));
    assertEquals("Service move(int,long) returns long, which is not a java.lang.String",
        wrongType.getMessage());
    assertThrows(TRADEBadArgumentsException.class, () -> service("fail").call(boolean.class));
    assertEquals(before, motor.invocations, "checked before invoking");
  }

  @Test
  void singleArrayArgumentIsPassedAsTheArgument() throws TRADEException {
    String[] words = {"a", "b"};
    assertSame(words, service("echo").call(String[].class, (Object) words));
    assertSame(words, service("echo").call(String[].class, words));
  }
}
