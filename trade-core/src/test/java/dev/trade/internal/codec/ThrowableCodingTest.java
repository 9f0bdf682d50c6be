package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.codec;
import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEInvocationException;
import dev.trade.TRADERemoteException;
import dev.trade.internal.codec.TestTypes.NoMessageException;
import dev.trade.internal.codec.TestTypes.RobotException;
import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.Test;

class ThrowableCodingTest {
  private final Codec codec = codec();

  private Throwable roundTrip(Throwable t, Codec decoder) throws Exception {
    return (Throwable) decoder.decode(codec.encode(t), loader());
  }

  @Test
  void knownExceptionsAreRebuiltAsThemselvesWithCauses() throws Exception {
    IOException io = new IOException("disk gone");
    RobotException robot = new RobotException("arm stuck", io);
    IllegalStateException top = new IllegalStateException("cannot move", robot);

    Throwable back = roundTrip(top, codec);
    assertSame(IllegalStateException.class, back.getClass());
    assertEquals("cannot move", back.getMessage());
    assertArrayEquals(top.getStackTrace(), back.getStackTrace());
    assertSame(RobotException.class, back.getCause().getClass());
    assertEquals("arm stuck", back.getCause().getMessage());
    assertSame(IOException.class, back.getCause().getCause().getClass());
    assertEquals("disk gone", back.getCause().getCause().getMessage());
    assertArrayEquals(io.getStackTrace(), back.getCause().getCause().getStackTrace());
    assertNull(back.getCause().getCause().getCause());
  }

  @Test
  void noArgumentConstructorIsUsedWhenThereIsNoOther() throws Exception {
    NoMessageException e = new NoMessageException();
    e.initCause(new ArithmeticException("zero"));
    Throwable back = roundTrip(e, codec);
    assertSame(NoMessageException.class, back.getClass());
    assertEquals("zero", back.getCause().getMessage());
  }

  @Test
  void refusedClassBecomesRemoteExceptionWithNameMessageAndStack() throws Exception {
    RobotException robot = new RobotException("arm stuck", new IllegalArgumentException("bad"));
    Throwable back = roundTrip(robot, TestTypes.strangerCodec());
    TRADERemoteException remote = assertInstanceOf(TRADERemoteException.class, back);
    assertEquals(RobotException.class.getName(), remote.getRemoteTypeName());
    assertEquals(RobotException.class.getName() + ": arm stuck [not received as itself: to receive"
        + " it, have " + RobotException.class.getName() + " on this JVM's class path and add it (or "
        + RobotException.class.getPackageName() + ".*) to the SERIALIZATIONALLOWLIST setting]",
        remote.getMessage());
    assertEquals("arm stuck", remote.getRemoteMessage());
    assertArrayEquals(robot.getStackTrace(), remote.getStackTrace());
    assertSame(IllegalArgumentException.class, remote.getCause().getClass()); // java.lang is allowed
  }

  @Test
  void unknownClassNameBecomesRemoteException() throws Exception {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.THROWABLE);
    out.writeText("com.example.GripperJamException");
    out.writeNullableText("jammed");
    out.writeVarUInt(1);
    out.writeNullableText(null);
    out.writeNullableText(null);
    out.writeNullableText(null);
    out.writeText("com.example.Gripper");
    out.writeText("close");
    out.writeNullableText("Gripper.java");
    out.writeInt(42);
    out.writeByte(Tags.NULL);
    Throwable back = (Throwable) codec.decode(out.toByteArray(), loader());
    TRADERemoteException remote = assertInstanceOf(TRADERemoteException.class, back);
    assertEquals("com.example.GripperJamException", remote.getRemoteTypeName());
    assertTrue(remote.getMessage().startsWith("com.example.GripperJamException: jammed ["), remote.getMessage());
    assertEquals(new StackTraceElement("com.example.Gripper", "close", "Gripper.java", 42),
        remote.getStackTrace()[0]);
  }

  @Test
  void remoteExceptionsTravelOnAsTheOriginal() throws Exception {
    TRADERemoteException remote =
        new TRADERemoteException("com.example.GripperJamException", "jammed", null);
    Throwable back = roundTrip(remote, codec);
    TRADERemoteException again = assertInstanceOf(TRADERemoteException.class, back);
    assertEquals("com.example.GripperJamException", again.getRemoteTypeName());
    assertEquals(remote.getMessage(), again.getMessage());
  }

  @Test
  void tradeExceptionsAreAllowedByDefault() throws Exception {
    TRADEInvocationException e = new TRADEInvocationException("failed", new RuntimeException("x"));
    Throwable back = roundTrip(e, TestTypes.strangerCodec());
    assertSame(TRADEInvocationException.class, back.getClass());
    assertSame(RuntimeException.class, back.getCause().getClass());
  }

  @Test
  void cyclicCauseChainIsCut() throws Exception {
    Exception a = new Exception("a");
    Exception b = new Exception("b", a);
    a.initCause(b);
    Throwable back = roundTrip(a, codec);
    assertEquals("b", back.getCause().getMessage());
    assertNull(back.getCause().getCause());
  }

  @Test
  void stackIsCutAtMaxStackFrames() throws Exception {
    Codec few = TestTypes.codec(new Limits(1 << 20, 64, 1 << 20, 3));
    Exception e = new Exception("deep");
    Throwable back = (Throwable) few.decode(few.encode(e), loader());
    assertEquals(3, back.getStackTrace().length);
    assertEquals(e.getStackTrace()[0], back.getStackTrace()[0]);
  }

  @Test
  void exceptionsNestedInOtherValues() throws Exception {
    Object back = codec.decode(codec.encode(List.of(new IllegalArgumentException("bad"))), loader());
    assertEquals("bad", ((Throwable) ((List<?>) back).get(0)).getMessage());
  }

  @Test
  void nullMessageStaysNull() throws Exception {
    Throwable back = roundTrip(new UnsupportedOperationException(), codec);
    assertNull(back.getMessage());
    assertTrue(back instanceof UnsupportedOperationException);
  }
}
