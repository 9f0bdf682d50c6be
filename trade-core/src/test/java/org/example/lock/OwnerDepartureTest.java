package org.example.lock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADELockInfo;
import dev.trade.TRADELockedException;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The container of a lock's owner leaves: the services' container ends its leases as soon as it
 * sees it go, not when they expire; an owner that is only slow keeps its lease.
 */
class OwnerDepartureTest {
  private static final Duration LONG = Duration.ofSeconds(30);

  @RegisterExtension final Hubs net = new Hubs();

  private final Joint head = new Joint();

  private static TRADEServiceInfo move(TRADEContainer x) {
    Await.until(LONG, () -> LocksTest.moves(x, "head").size() == 1, x.getName() + " sees the head");
    return LocksTest.moves(x, "head").get(0);
  }

  @Test
  void aWaiterGetsTheServicesPromptlyWhenTheOwnersContainerLeaves() throws Exception {
    // A lease of a minute: a grant within the waiter's 30 s can only come from the departure.
    TRADEContainer robot = net.keep(Hubs.hubBuilder("robot").property("FAILURETIMEOUT", "60000")
        .build());
    robot.registerAllServices(head, "head");
    TRADEContainer owner = net.spoke("owner", robot);
    TRADEContainer next = net.spoke("next", robot);
    TRADELock held = owner.lock(List.of(move(owner)), Duration.ZERO);
    TRADEServiceInfo turn = move(next);
    CompletableFuture<TRADELock> waiting = CompletableFuture.supplyAsync(() -> {
      try {
        return next.lock(List.of(turn), LONG);
      } catch (Exception e) {
        throw new IllegalStateException(e);
      }
    });
    Await.until(LONG, () -> waiters(robot) == 1, "next's request waits at the robot");
    owner.close(); // leaves without releasing: its lease would last another minute
    TRADELock got = waiting.get(60, TimeUnit.SECONDS);
    assertEquals(4, turn.call(got.getId(), Integer.class, 4));
    for (TRADELockInfo i : robot.getLocks()) {
      assertTrue(!i.getLockId().equals(held.getId()), "the departed owner's lock is gone: " + i);
    }
    got.close();
  }

  @Test
  void anOwnerThatIsOnlySlowKeepsItsLease() throws Exception {
    TRADEContainer robot = net.hub("robot"); // FAILURETIMEOUT's default: a lease of 3 s
    robot.registerAllServices(head, "head");
    TRADEContainer owner = net.spoke("owner", robot);
    TRADEContainer next = net.spoke("next", robot);
    TRADELock held = owner.lock(List.of(move(owner)), Duration.ZERO);
    // Services of the owner leave, the owner stays: not a departure.
    Joint own = new Joint();
    owner.registerAllServices(own, "own");
    Await.until(LONG, () -> LocksTest.moves(robot, "own").size() == 1, "the robot sees owner's joint");
    owner.deregister(own);
    Await.until(LONG, () -> LocksTest.moves(robot, "own").isEmpty(), "the robot sees it leave");
    // The owner makes no call for more than two leases while another container waits.
    TRADELockedException refused = assertThrows(TRADELockedException.class,
        () -> next.lock(List.of(move(next)), Duration.ofMillis(7000)));
    assertTrue(refused.getMessage().contains("held by lock " + held.getId() + " of container owner"),
        refused.getMessage());
    assertTrue(held.getDropped().isEmpty(), "nothing dropped: " + held.getDropped());
    assertEquals(6, move(owner).call(held.getId(), Integer.class, 6), "still the owner's");
    held.close();
  }

  private static int waiters(TRADEContainer x) {
    try {
      return (int) x.getLocks().stream().filter(i -> !i.isHolding()).count();
    } catch (Exception e) {
      throw new IllegalStateException(e);
    }
  }

  @Test
  void anOwnerWithALongerFailureTimeoutRenewsWithinTheServicesShorterLease() throws Exception {
    TRADEContainer robot = net.hub("robot"); // a lease of 3 s
    robot.registerAllServices(head, "head");
    // Left to its own FAILURETIMEOUT, the owner would renew every 20 s, long after the lease ended.
    TRADEContainer owner = net.keep(Hubs.spokeBuilder("owner", robot)
        .property("FAILURETIMEOUT", "60000").build());
    TRADEContainer next = net.spoke("next", robot);
    TRADELock held = owner.lock(List.of(move(owner)), Duration.ZERO);
    TRADELockedException refused = assertThrows(TRADELockedException.class,
        () -> next.lock(List.of(move(next)), Duration.ofMillis(8000)));
    assertTrue(refused.getMessage().contains("held by lock " + held.getId()), refused.getMessage());
    assertEquals(8, move(owner).call(held.getId(), Integer.class, 8), "still the owner's");
    held.close();
  }
}
