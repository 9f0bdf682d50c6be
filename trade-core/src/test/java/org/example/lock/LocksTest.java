package org.example.lock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADELockInfo;
import dev.trade.TRADELockedException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.UncheckedTRADEException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Locks over services of three containers, taken, enforced and released from others; a fourth
 * container only looks.
 */
class LocksTest {
  private static final Duration LONG = Duration.ofSeconds(30);

  @RegisterExtension final Hubs net = new Hubs();

  private TRADEContainer a;
  private TRADEContainer b;
  private TRADEContainer c;
  private TRADEContainer d;
  private final Joint head = new Joint();
  private final Joint leftLeg = new Joint();
  private final Joint rightLeg = new Joint();

  @BeforeEach
  void fourContainers() throws Exception {
    a = net.hub("a");
    b = net.spoke("b", a);
    c = net.spoke("c", a);
    d = net.spoke("d", a);
    a.registerAllServices(head, "body", "head");
    b.registerAllServices(leftLeg, "body", "legs");
    c.registerAllServices(rightLeg, "body", "legs");
    for (TRADEContainer x : List.of(a, b, c, d)) {
      Await.until(LONG, () -> moves(x, "body").size() == 3, x.getName() + " sees every joint");
    }
  }

  static List<TRADEServiceInfo> moves(TRADEContainer x, String group) {
    return List.copyOf(x.getAvailableServices(
        new TRADEServiceConstraints().name("move").inGroups(group)));
  }

  private static TRADEServiceInfo move(TRADEContainer x, String containerName) {
    for (TRADEServiceInfo s : moves(x, "body")) {
      if (s.getContainerName().equals(containerName)) {
        return s;
      }
    }
    throw new AssertionError("no move of " + containerName + " seen from " + x.getName());
  }

  @Test
  void aLockOverThreeContainersIsEnforcedWhereTheServicesLive() throws Exception {
    try (TRADELock lock = d.lock(moves(d, "body"), Duration.ZERO)) {
      assertEquals(3, lock.getServices().size());
      for (TRADEServiceInfo s : moves(d, "body")) {
        assertEquals(7, s.call(lock.getId(), Integer.class, 7), "under the lock, from its owner");
      }
      TRADELockedException refused = assertThrows(TRADELockedException.class,
          () -> move(b, "a").call(int.class, 1));
      assertTrue(refused.getMessage().contains("of container d"), refused.getMessage());
      assertTrue(refused.getMessage().contains(lock.getId().toString()), refused.getMessage());
      // The local caller is refused as well: the check is in the providing container.
      assertThrows(TRADELockedException.class, () -> move(a, "a").call(int.class, 1));
      // The lock id is no pass for another container.
      assertThrows(TRADELockedException.class, () -> move(b, "c").call(lock.getId(), int.class, 1));
    }
    assertEquals(1, move(b, "a").call(int.class, 1), "free after release");
  }

  @Test
  void callsUnderAReleasedLockFail() throws Exception {
    TRADELock lock = d.lock(moves(d, "legs"), Duration.ZERO);
    lock.release();
    assertTrue(lock.isReleased());
    TRADELockedException e = assertThrows(TRADELockedException.class,
        () -> move(d, "b").call(lock.getId(), int.class, 1));
    assertTrue(e.getMessage().contains("is not held by container d"), e.getMessage());
    assertThrows(TRADEBadArgumentsException.class, lock::release, "released twice");
  }

  @Test
  void tradesFormsReturnNullWhileAnyServiceIsHeld() throws Exception {
    UUID legs = b.lockServicesContainAll(List.of("body", "legs"));
    assertNotNull(legs);
    assertNull(c.lockServicesContainOne(List.of("head", "legs")), "the legs are held");
    // Two legs of three services each (move, enter, leave): nothing of the refused request.
    assertEquals(6, b.getLocks().size(), "nothing of the refused request stays locked");
    UUID headLock = c.lockServicesContainAll(List.of("head"));
    assertNotNull(headLock, "the head was free");
    assertEquals(5, move(c, "a").call(headLock, Integer.class, 5));
    b.releaseLock(legs);
    c.releaseLock(headLock);
    assertTrue(d.getLocks().isEmpty());
  }

  @Test
  void badInputGetsTypedErrorsAndLeavesNothingLocked() throws Exception {
    assertThrows(TRADEBadArgumentsException.class, () -> d.lock(List.of(), Duration.ZERO));
    assertThrows(TRADEBadArgumentsException.class,
        () -> d.lock(new TRADEServiceConstraints().inGroups("nothing"), Duration.ZERO));
    UncheckedTRADEException none = assertThrows(UncheckedTRADEException.class,
        () -> d.lockServicesContainAll(List.of("nothing")));
    assertTrue(none.getCause() instanceof TRADEBadArgumentsException, none.getMessage());
    assertThrows(UncheckedTRADEException.class, () -> d.lockServicesContainOne(List.of()));
    assertThrows(TRADEBadArgumentsException.class, () -> d.releaseLock(UUID.randomUUID()));
    TRADEServiceInfo gone = move(d, "c");
    c.deregister(rightLeg);
    Await.until(LONG, () -> moves(d, "legs").size() == 1, "d sees the right leg go");
    assertThrows(dev.trade.TRADEServiceUnavailableException.class,
        () -> d.lock(List.of(move(d, "b"), gone), Duration.ZERO));
    assertTrue(d.getLocks().isEmpty(), "nothing left locked: " + d.getLocks());

    UUID held = b.lockServicesContainAll(List.of("head"));
    TRADENotAuthorizedException notYours = assertThrows(TRADENotAuthorizedException.class,
        () -> d.releaseLock(held));
    assertTrue(notYours.getMessage().contains("only its owner releases it"), notYours.getMessage());
    assertEquals(3, d.getLocks().size(), "the head's three services are still held");
    b.releaseLock(held);
  }

  @Test
  void aWaitingLockerIsToldWhoHoldsThenGetsItOnRelease() throws Exception {
    TRADELock first = b.lock(List.of(move(b, "a")), Duration.ZERO);
    TRADELockedException told = assertThrows(TRADELockedException.class,
        () -> c.lock(List.of(move(c, "a")), Duration.ofMillis(50)));
    assertTrue(told.getMessage().contains("held by lock " + first.getId() + " of container b"),
        told.getMessage());
    CompletableFuture<TRADELock> second = CompletableFuture.supplyAsync(() -> {
      try {
        return c.lock(List.of(move(c, "a")), LONG);
      } catch (Exception e) {
        throw new IllegalStateException(e);
      }
    });
    Await.until(LONG, () -> waiters(d) == 1, "d sees c's request wait");
    TRADELockInfo waiting = null;
    for (TRADELockInfo i : d.getLocks()) {
      if (!i.isHolding()) {
        waiting = i;
      }
    }
    assertNotNull(waiting);
    assertEquals("c", waiting.getContainerName());
    first.close();
    TRADELock got = second.get();
    assertEquals(3, move(c, "a").call(got.getId(), Integer.class, 3));
    got.close();
  }

  private static int waiters(TRADEContainer x) {
    try {
      int n = 0;
      for (TRADELockInfo i : x.getLocks()) {
        n += i.isHolding() ? 0 : 1;
      }
      return n;
    } catch (Exception e) {
      throw new IllegalStateException(e);
    }
  }

  @Test
  void aCallThatAskedToWaitRunsOnceTheLockIsReleased() throws Exception {
    TRADELock lock = b.lock(List.of(move(b, "c")), Duration.ZERO);
    CompletableFuture<Integer> waiting = CompletableFuture.supplyAsync(() -> {
      try {
        return move(d, "c").withTimeout(LONG).waitingForLock().call(Integer.class, 9);
      } catch (Exception e) {
        throw new IllegalStateException(e);
      }
    });
    assertFalse(waiting.isDone());
    lock.close();
    assertEquals(9, waiting.get());
    TRADELock again = b.lock(List.of(move(b, "c")), Duration.ZERO);
    TRADELockedException e = assertThrows(TRADELockedException.class,
        () -> move(d, "c").withTimeout(Duration.ofSeconds(3)).waitingForLock().call(int.class, 1));
    assertTrue(e.getMessage().contains("of container b"), e.getMessage());
    again.close();
  }

  @Test
  void introspectionFromAFourthContainer() throws Exception {
    TRADELock lock = b.lock(moves(b, "body"), Duration.ZERO);
    List<TRADELockInfo> seen = d.getLocks();
    assertEquals(3, seen.size(), seen.toString());
    for (TRADELockInfo i : seen) {
      assertTrue(i.isHolding());
      assertEquals(lock.getId(), i.getLockId());
      assertEquals("b", i.getContainerName());
      assertEquals(b.getId(), i.getContainerId());
      assertTrue(i.getFencingToken() > 0);
      assertFalse(i.getSince().isAfter(java.time.Instant.now().plusSeconds(60)));
    }
    lock.close();
    assertTrue(d.getLocks().isEmpty());
  }

  @Test
  void aServiceThatLeavesIsDroppedAndTheHolderSeesIt() throws Exception {
    TRADELock lock = d.lock(moves(d, "body"), Duration.ZERO);
    TRADEServiceInfo right = move(d, "c");
    c.close();
    Await.until(LONG, () -> lock.getDropped().contains(right), "the lock drops c's leg");
    assertEquals(1, lock.getDropped().size());
    TRADELockedException e = assertThrows(TRADELockedException.class,
        () -> right.call(lock.getId(), int.class, 1));
    assertTrue(e.getMessage().contains("any more"), e.getMessage());
    assertEquals(2, move(d, "b").call(lock.getId(), Integer.class, 2), "the rest stays held");
    lock.close();
  }
}
