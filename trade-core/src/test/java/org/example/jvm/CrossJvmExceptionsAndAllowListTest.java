package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADERemoteException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.io.IOException;
import java.util.Arrays;
import org.example.jvm.RemoteTypes.ArmJammedException;
import org.example.jvm.RemoteTypes.Pose;
import org.junit.jupiter.api.Test;

/**
 * Exceptions thrown by a {@link ProviderMain} JVM's services cross to this JVM, through real
 * sockets on loopback, rebuilt as their own class, or as a {@link TRADERemoteException} where
 * their class is unknown or not allowed here; a value of a class not allowed here is refused by
 * name, and a caller with no allow list settings still decodes the types its own code names. The
 * values themselves: {@link CrossJvmValuesTest}.
 */
class CrossJvmExceptionsAndAllowListTest extends ProviderFixture {
  @Test
  void serviceExceptionsAreRebuiltAsTheirOwnClass() {
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class,
        () -> service("fail").call(void.class, "state"));
    assertSame(IllegalStateException.class, e.getCause().getClass());
    assertEquals("jammed", e.getCause().getMessage());
    assertTrue(Arrays.stream(e.getCause().getStackTrace())
        .anyMatch(f -> f.getClassName().equals(ProviderMain.Services.class.getName())
            && f.getMethodName().equals("fail")), "the provider's stack trace travels");

    e = assertThrows(TRADEInvocationException.class, () -> service("fail").call(void.class, "jammed"));
    ArmJammedException jammed = assertInstanceOf(ArmJammedException.class, e.getCause());
    assertEquals("gripper 2 jammed", jammed.getMessage());
    assertSame(IOException.class, jammed.getCause().getClass());
    assertEquals("sensor offline", jammed.getCause().getMessage());
  }

  @Test
  void exceptionOfAClassUnknownHereArrivesAsRemoteException() {
    assertThrows(ClassNotFoundException.class, () -> Class.forName(PROVIDER_ONLY));
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class,
        () -> service("fail").call(void.class, PROVIDER_ONLY));
    TRADERemoteException remote = assertInstanceOf(TRADERemoteException.class, e.getCause());
    assertEquals(PROVIDER_ONLY, remote.getRemoteTypeName());
    assertEquals("thrown by " + PROVIDER_ONLY, remote.getRemoteMessage());
    assertTrue(remote.getMessage().startsWith(PROVIDER_ONLY + ": thrown by " + PROVIDER_ONLY), remote.getMessage());
    assertTrue(remote.getStackTrace().length > 0, "the remote stack trace travels");
  }

  @Test
  void exceptionOfAClassNotAllowedHereArrivesAsRemoteException() {
    TRADEInvocationException e = assertThrows(TRADEInvocationException.class,
        () -> service("fail").call(void.class, "secret"));
    TRADERemoteException remote = assertInstanceOf(TRADERemoteException.class, e.getCause());
    assertEquals("org.example.jvm.secret.Secrets$SecretException", remote.getRemoteTypeName());
    assertTrue(remote.getRemoteMessage().endsWith("the code is 1234"), remote.getRemoteMessage());
    assertTrue(remote.getMessage().endsWith("add it (or org.example.jvm.secret.*) to the"
        + " SERIALIZATIONALLOWLIST setting]"), remote.getMessage());
  }

  @Test
  void aCallerWithoutAllowListSettingsDecodesTheTypesItsOwnCodeNames() throws TRADEException {
    try (TRADEContainer plain = TRADEContainer.builder().name("plain")
        .property("CONNECTCONTAINERS", providerAddress)
        .build()) {
      TRADEServiceConstraints move = new TRADEServiceConstraints().inGroups("provider").name("move");
      Await.until(START, () -> !plain.getAvailableServices(move).isEmpty(), "move on plain");
      TRADEServiceInfo s = plain.getAvailableService(move);
      assertEquals(new Pose(3, 2, 0, "map"), s.call(Pose.class, new Pose(1, 2, 0, "map"), 2.0));
      TRADESerializationException e = assertThrows(TRADESerializationException.class,
          () -> plain.getAvailableService(new TRADEServiceConstraints().inGroups("provider")
              .name("secretCode")).call(Object.class));
      assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    }
  }

  @Test
  void valueOfAClassNotAllowedHereIsRefusedByName() throws TRADEException {
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> service("secretCode").call(Object.class));
    assertTrue(e.getMessage().contains("org.example.jvm.secret.Secrets$Code"), e.getMessage());
    assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    assertEquals("the link still works", echo("the link still works"));
  }
}
