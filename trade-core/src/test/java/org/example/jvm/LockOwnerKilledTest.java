package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADELockInfo;
import dev.trade.TRADELockedException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The process owning a lock is killed with SIGKILL while a request from another container waits
 * for the same service: the service's container frees it when it sees the owner leave (its
 * sockets end), at the latest when the lease ends (FAILURETIMEOUT, 3 s, after the owner's last
 * renewal), and the waiting request gets it.
 */
class LockOwnerKilledTest {
  private static final Duration START = Duration.ofSeconds(60);
  /**
   * The lease (FAILURETIMEOUT's default) and generous room for a loaded machine: that the lease
   * ends at 3 s exactly is LeaseTableTest's, on a fake clock; here, that the lock passes on.
   */
  private static final long LIMIT_MS = 3000 + 10_000;

  /** The locked effector. */
  public static final class Head {
    @TRADEService
    public int turn(int degrees) {
      return degrees;
    }
  }

  @Test
  void theNextWaiterGetsTheServicesOfAKilledOwner() throws Exception {
    TRADEContainer.Builder robotBuilder = TRADEContainer.builder().name("robot")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0");
    try (TRADEContainer robot = robotBuilder.build()) {
      robot.registerAllServices(new Head(), "head");
      String address = robot.getServerAddresses().get(0);
      try (TRADEContainer next = TRADEContainer.builder().name("next")
              .property("CONNECTCONTAINERS", address).build();
          JvmProcess owner = JvmProcess.start(LockOwnerMain.class, List.of(),
              "CONTAINERNAME=owner", "CONNECTCONTAINERS=" + address)) {
        UUID held = UUID.fromString(owner.awaitLine("HELD ", START).substring(5).trim());
        TRADEServiceInfo turn = next.waitForService(
            new TRADEServiceConstraints().name("turn"), START);
        TRADELockedException refused = assertThrows(TRADELockedException.class,
            () -> turn.call(int.class, 5));
        assertTrue(refused.getMessage().contains("of container owner"), refused.getMessage());

        CompletableFuture<TRADELock> waiting = CompletableFuture.supplyAsync(() -> {
          try {
            return next.lock(List.of(turn), Duration.ofSeconds(60));
          } catch (Exception e) {
            throw new IllegalStateException(e);
          }
        });
        Await.until(START, () -> waiters(robot) == 1, "next's request waits");
        long killedAt = System.nanoTime();
        owner.kill();
        TRADELock got = waiting.get(60, TimeUnit.SECONDS);
        long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - killedAt);
        System.out.println("lock of a killed owner passed on after " + ms + " ms");
        assertTrue(ms <= LIMIT_MS, "passed on after " + ms + " ms");
        assertEquals(7, turn.call(got.getId(), Integer.class, 7));
        for (TRADELockInfo i : robot.getLocks()) {
          assertTrue(!i.getLockId().equals(held), "the killed owner's lock is gone: " + i);
        }
        got.close();
      }
    }
  }

  private static int waiters(TRADEContainer x) {
    try {
      return (int) x.getLocks().stream().filter(i -> !i.isHolding()).count();
    } catch (Exception e) {
      throw new IllegalStateException(e);
    }
  }
}
