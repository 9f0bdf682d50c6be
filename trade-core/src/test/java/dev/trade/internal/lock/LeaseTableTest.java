package dev.trade.internal.lock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The lease table's decisions, on a fake clock: every {@code now} is a number the test picks. */
class LeaseTableTest {
  private static final long LEASE = TimeUnit.SECONDS.toNanos(3);
  private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);
  private static final UUID A = UUID.fromString("00000000-0000-0000-0000-00000000000a");
  private static final UUID B = UUID.fromString("00000000-0000-0000-0000-00000000000b");

  private final LeaseTable table = new LeaseTable(LEASE);

  private static LeaseTable.Claim claim(UUID owner) {
    return new LeaseTable.Claim(UUID.randomUUID(), owner, "");
  }

  private LeaseTable.Outcome grant(LeaseTable.Claim c, long now, long... services) throws Exception {
    return table.tryGrant(c, services, Long.MAX_VALUE, now, 0);
  }

  @Test
  void grantsAllOrNothingAndNamesTheHolder() throws Exception {
    LeaseTable.Claim first = claim(A);
    assertTrue(grant(first, 0, 1, 2).granted());
    LeaseTable.Outcome refused = grant(claim(B), 0, 3, 2);
    assertFalse(refused.granted());
    assertEquals(2, refused.blocker().service());
    assertEquals(first, refused.blocker().claim());
    assertTrue(refused.blocker().holding());
    // Nothing of the refused request was taken: service 3 is free.
    assertTrue(grant(claim(B), 0, 3).granted());
  }

  @Test
  void tokensIncreasePerServiceWithEveryGrant() throws Exception {
    LeaseTable.Claim c1 = claim(A);
    long t1 = grant(c1, 0, 1).tokens().get(1L);
    table.release(c1.lock(), A, 0);
    LeaseTable.Claim c2 = claim(B);
    long t2 = grant(c2, 0, 1).tokens().get(1L);
    assertTrue(t2 > t1, t2 + " > " + t1);
  }

  @Test
  void aLeaseEndsAtItsExpiryUnlessRenewed() throws Exception {
    LeaseTable.Claim c = claim(A);
    grant(c, 0, 1);
    assertFalse(grant(claim(B), LEASE - 1, 1).granted());
    assertTrue(grant(claim(B), LEASE, 1).granted(), "free exactly when the lease ends");

    LeaseTable.Claim d = claim(A);
    grant(d, 10 * LEASE, 2);
    Map<UUID, long[]> renewed = table.renew(A, List.of(d.lock()), 10 * LEASE + LEASE - MS);
    assertEquals(1, renewed.size());
    assertFalse(grant(claim(B), 10 * LEASE + 2 * LEASE - 2 * MS, 2).granted(), "renewed");
    assertTrue(grant(claim(B), 10 * LEASE + 2 * LEASE - MS, 2).granted(), "ended a lease after renewal");
  }

  @Test
  void onlyTheOwnerRenewsAndAnEndedLeaseIsNotRenewed() throws Exception {
    LeaseTable.Claim c = claim(A);
    grant(c, 0, 1);
    assertTrue(table.renew(B, List.of(c.lock()), MS).isEmpty());
    assertTrue(table.renew(A, List.of(c.lock()), LEASE).isEmpty(), "ended at LEASE");
  }

  @Test
  void callsRunOnlyUnderTheHoldersLockAndCurrentToken() throws Exception {
    LeaseTable.Claim c = claim(A);
    long token = grant(c, 0, 1).tokens().get(1L);
    assertTrue(table.admit(2, null, 0, B, 0).admitted(), "an unlocked service");
    assertTrue(table.admit(1, c.lock(), token, A, 0).admitted());
    LeaseTable.Admission plain = table.admit(1, null, 0, B, 0);
    assertFalse(plain.admitted());
    assertTrue(plain.mayWait());
    assertEquals(c, plain.blocker().claim());
    assertFalse(table.admit(1, c.lock(), token, B, 0).admitted(), "from another container");
    assertFalse(table.admit(1, c.lock(), token - 1, A, 0).admitted(), "another token");
    assertFalse(table.admit(1, UUID.randomUUID(), token, A, 0).admitted(), "another lock");
  }

  @Test
  void aStaleOwnerIsRefusedByFencingTokenAfterItsLeaseMoved() throws Exception {
    // The owner on the far side of a partition stops renewing; its lease ends; another lock takes
    // the service. The old owner's calls, still carrying its lock and token, are refused.
    LeaseTable.Claim old = claim(A);
    long oldToken = grant(old, 0, 1).tokens().get(1L);
    LeaseTable.Claim next = claim(B);
    long nextToken = grant(next, LEASE, 1).tokens().get(1L);
    assertTrue(nextToken > oldToken);
    LeaseTable.Admission a = table.admit(1, old.lock(), oldToken, A, LEASE + MS);
    assertFalse(a.admitted());
    assertFalse(a.mayWait());
    assertTrue(a.why().contains("fencing token " + oldToken + " is older than the service's latest"
        + " grant, " + nextToken), a.why());
    assertTrue(table.admit(1, next.lock(), nextToken, B, LEASE + MS).admitted());
    // Once the new holder releases, the stale token still does not run the service.
    table.release(next.lock(), B, LEASE + MS);
    assertFalse(table.admit(1, old.lock(), oldToken, A, LEASE + 2 * MS).admitted());
    assertTrue(table.admit(1, null, 0, A, LEASE + 2 * MS).admitted(), "free for plain calls");
  }

  @Test
  void waitersAreServedFirstComeFirstServedPerService() throws Exception {
    LeaseTable.Claim holder = claim(A);
    grant(holder, 0, 1, 2);
    LeaseTable.Claim early = claim(B);
    long earlyTicket = table.enqueue(early, new long[] {1, 2}, 0);
    LeaseTable.Claim late = claim(B);
    long lateTicket = table.enqueue(late, new long[] {2}, 0);
    table.release(holder.lock(), A, MS);
    LeaseTable.Outcome lateFirst = table.tryGrant(late, new long[] {2}, lateTicket, MS, 0);
    assertFalse(lateFirst.granted(), "an earlier request waits for service 2");
    assertEquals(early, lateFirst.blocker().claim());
    assertFalse(lateFirst.blocker().holding());
    assertFalse(grant(claim(A), MS, 1).granted(), "a try does not pass queued requests");
    assertTrue(table.tryGrant(early, new long[] {1, 2}, earlyTicket, MS, 0).granted());
    table.leave(earlyTicket);
    table.release(early.lock(), B, 2 * MS);
    assertTrue(table.tryGrant(late, new long[] {2}, lateTicket, 2 * MS, 0).granted());
  }

  @Test
  void overlappingWaitersCannotBlockEachOther() throws Exception {
    // x waits for {1,2}, y for {2,3}, z for {3,1}: whichever came first heads every queue it is in.
    LeaseTable.Claim holder = claim(A);
    grant(holder, 0, 1, 2, 3);
    LeaseTable.Claim x = claim(B);
    LeaseTable.Claim y = claim(B);
    LeaseTable.Claim z = claim(B);
    long tx = table.enqueue(x, new long[] {1, 2}, 0);
    long ty = table.enqueue(y, new long[] {2, 3}, 0);
    long tz = table.enqueue(z, new long[] {3, 1}, 0);
    table.release(holder.lock(), A, 0);
    assertFalse(table.tryGrant(z, new long[] {3, 1}, tz, 0, 0).granted());
    assertFalse(table.tryGrant(y, new long[] {2, 3}, ty, 0, 0).granted());
    assertTrue(table.tryGrant(x, new long[] {1, 2}, tx, 0, 0).granted());
  }

  @Test
  void badInputIsRefusedAndLeavesNothingHeld() throws Exception {
    LeaseTable.Claim c = claim(A);
    grant(c, 0, 1);
    assertThrows(TRADEBadArgumentsException.class, () -> grant(c, 0, 2), "a lock id taken twice");
    assertTrue(grant(claim(B), 0, 2).granted(), "service 2 stayed free");
    TRADENotAuthorizedException e = assertThrows(TRADENotAuthorizedException.class,
        () -> table.release(c.lock(), B, 0));
    assertTrue(e.getMessage().contains("only its owner releases it"), e.getMessage());
    assertFalse(table.admit(1, null, 0, B, 0).admitted(), "still held after the refused release");
    assertEquals(0, table.release(UUID.randomUUID(), A, 0), "an unknown lock");
    assertEquals(1, table.release(c.lock(), A, 0));
    assertEquals(0, table.release(c.lock(), A, 0), "released already");
  }

  @Test
  void aServiceThatLeavesIsDroppedFromItsLease() throws Exception {
    LeaseTable.Claim c = claim(A);
    grant(c, 0, 1, 2);
    table.drop(2);
    long[] still = table.renew(A, List.of(c.lock()), MS).get(c.lock());
    assertEquals(1, still.length);
    assertEquals(1, still[0]);
    table.drop(1);
    assertNull(table.renew(A, List.of(c.lock()), MS).get(c.lock()), "a lease with no service ends");
  }

  @Test
  void listShowsHoldersThenWaitersWithTheirExpiry() throws Exception {
    LeaseTable.Claim c = claim(A);
    grant(c, 0, 1);
    LeaseTable.Claim w = claim(B);
    table.enqueue(w, new long[] {1}, 5);
    List<LeaseTable.Row> rows = table.list(LEASE / 3);
    assertEquals(2, rows.size());
    assertTrue(rows.get(0).holding());
    assertEquals(c, rows.get(0).claim());
    assertEquals(LEASE - LEASE / 3, rows.get(0).expiresInNanos());
    assertFalse(rows.get(1).holding());
    assertEquals(w, rows.get(1).claim());
    assertEquals(5, rows.get(1).sinceMillis());
    assertTrue(table.list(LEASE).stream().noneMatch(LeaseTable.Row::holding), "ended");
  }
  @Test
  void anOwnerSeenToLeaveLosesItsLeasesAtOnce() throws Exception {
    LeaseTable.Claim gone = claim(A);
    long oldToken = grant(gone, 0, 1, 2).tokens().get(1L);
    LeaseTable.Claim other = claim(B);
    grant(other, 0, 3);
    assertEquals(1, table.ownerLeft(A, MS), "one lease of A ended");
    // Long before the lease would have expired, the services are free; B's lease is untouched.
    LeaseTable.Outcome next = grant(claim(B), 2 * MS, 1, 2);
    assertTrue(next.granted(), "free when the owner left, not at the lease's end");
    assertTrue(next.tokens().get(1L) > oldToken);
    assertFalse(grant(claim(A), 2 * MS, 3).granted(), "another owner's lease stays");
    assertTrue(table.renew(A, List.of(gone.lock()), 3 * MS).isEmpty(), "nothing left to renew");
    LeaseTable.Admission stale = table.admit(1, gone.lock(), oldToken, A, 3 * MS);
    assertFalse(stale.admitted());
    assertTrue(stale.why().contains("is older than the service's latest grant"), stale.why());
    assertEquals(0, table.ownerLeft(A, 4 * MS), "told twice: nothing more ends");
  }

  @Test
  void aSlowOwnerThatDidNotLeaveKeepsItsLease() throws Exception {
    LeaseTable.Claim slow = claim(A);
    grant(slow, 0, 1);
    table.ownerLeft(B, MS); // another container left
    // Renewed late, but within each lease: held for ten leases without one call.
    for (int i = 1; i <= 10; i++) {
      long now = i * (LEASE - MS);
      assertEquals(1, table.renew(A, List.of(slow.lock()), now).size(), "renewal " + i);
      assertFalse(grant(claim(B), now + MS, 1).granted(), "still held after renewal " + i);
    }
  }

  @Test
  void aRequestWaitingForALeaseIsWokenWhenItsOwnerLeaves() throws Exception {
    LeaseTable.Claim gone = claim(A);
    grant(gone, 0, 1);
    CompletableFuture<LeaseTable.Outcome> waiting =
        CompletableFuture.supplyAsync(() -> {
          try {
            // Its deadline is far beyond the lease: only the departure can grant it in time.
            return table.awaitGrant(claim(B), new long[] {1}, 1000 * LEASE, () -> 0, () -> 0);
          } catch (Exception e) {
            throw new IllegalStateException(e);
          }
        });
    Await.until(Duration.ofSeconds(30),
        () -> table.list(0).size() == 2, "the request waits");
    table.ownerLeft(A, 0);
    assertTrue(waiting.get(30, TimeUnit.SECONDS).granted());
  }

  @Test
  void aWaitingRequestOfAnOwnerThatLeavesIsWithdrawnAndBlocksNoOneBehindIt() throws Exception {
    grant(claim(A), 0, 1);
    LeaseTable.Claim leaving = claim(B);
    CompletableFuture<LeaseTable.Outcome> waiting = CompletableFuture.supplyAsync(() -> {
      try {
        return table.awaitGrant(leaving, new long[] {1, 2}, 1000 * LEASE, () -> 0, () -> 0);
      } catch (Exception e) {
        throw new IllegalStateException(e);
      }
    });
    Await.until(Duration.ofSeconds(30), () -> table.list(0).size() == 3, "the request waits");
    table.ownerLeft(B, 0);
    LeaseTable.Outcome o = waiting.get(30, TimeUnit.SECONDS);
    assertFalse(o.granted());
    assertNull(o.blocker());
    // Service 2 is free, and no request waits for it any more.
    assertTrue(grant(claim(A), 0, 2).granted());
    assertEquals(2, table.list(0).size(), table.list(0).toString());
  }
}
