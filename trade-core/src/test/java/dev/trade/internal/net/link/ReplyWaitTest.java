package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADETimeoutException;
import java.io.IOException;
import java.net.Socket;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Waiting for a reply, spinning or not: the reply arrives however late it comes, a failure (the
 * deadline's, completed by {@link Deadlines}, among them) reaches the caller, and no outcome
 * leaves the wait counted (a counted caller would stop every later lone caller from reading its
 * reply, and one counted as parked on its link would keep the link from being lent again).
 */
class ReplyWaitTest {
  private final ReplyWait wait = new ReplyWait();
  private final LoopbackLinks links = new LoopbackLinks();
  private Link link;

  @BeforeEach
  void link() throws IOException {
    link = links.link(UUID.randomUUID(), "peer", new Socket[1]);
  }

  @AfterEach
  void close() throws IOException {
    links.close();
  }

  @Test
  void aReplyInTimeIsReturnedWhetherItComesDuringTheSpinOrAfter() throws Exception {
    for (long delayMs : new long[] {0, 1, 50}) {
      CompletableFuture<byte[]> reply = new CompletableFuture<>();
      byte[] body = {(byte) delayMs};
      CompletableFuture.delayedExecutor(delayMs, TimeUnit.MILLISECONDS).execute(() -> reply.complete(body));
      long sent = System.nanoTime();
      assertArrayEquals(body, wait.await(link, false, reply, sent));
      assertEquals(0, wait.waiting());
      assertEquals(0, link.role.parked());
    }
  }

  @Test
  void aDeadlineThatPassesReachesTheWaitingCaller() {
    long sent = System.nanoTime();
    ExecutionException e = assertThrows(ExecutionException.class,
        () -> wait.await(link, false, failsAfter(100), sent));
    assertTrue(e.getCause() instanceof TRADETimeoutException, e.toString());
    long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - sent);
    assertTrue(waited >= 90, "gave up after " + waited + " ms");
    assertEquals(0, wait.waiting());
    assertEquals(0, link.role.parked());
  }

  /**
   * Whether {@link ReplyWait#borrow} borrows for a call made right after another: tried a few
   * times, since a pause of the test's thread (a collection) may put the two further apart than
   * lending pays for.
   */
  private boolean borrowsRightAfterACall(Link link) {
    for (int i = 0; i < 10; i++) {
      link.role.touch();
      if (wait.borrow(link)) {
        return true;
      }
    }
    return false;
  }

  /** A reply that fails as {@link Deadlines} fails it, after {@code ms}. */
  private static CompletableFuture<byte[]> failsAfter(long ms) {
    CompletableFuture<byte[]> reply = new CompletableFuture<>();
    CompletableFuture.delayedExecutor(ms, TimeUnit.MILLISECONDS)
        .execute(() -> reply.completeExceptionally(new TRADETimeoutException("deadline")));
    return reply;
  }

  @Test
  void aFailedCallReachesTheCaller() {
    IllegalStateException cause = new IllegalStateException("link lost");
    CompletableFuture<byte[]> reply = CompletableFuture.failedFuture(cause);
    long sent = System.nanoTime();
    ExecutionException e = assertThrows(ExecutionException.class,
        () -> wait.await(link, false, reply, sent));
    assertSame(cause, e.getCause());
    assertEquals(0, wait.waiting());
  }

  @Test
  void aLoneCallerReadsTheLinkAndNoOutcomeLeavesItCountedThere() throws Exception {
    assertFalse(wait.borrow(link), "the first call borrows: lending would not reach a next one");
    assertTrue(borrowsRightAfterACall(link), "a lone caller calling again soon reads its reply");
    assertTrue(link.role.callerWaits());
    long sent = System.nanoTime();
    assertArrayEquals(new byte[] {1}, wait.await(link, true,
        CompletableFuture.completedFuture(new byte[] {1}), sent));
    assertFalse(link.role.callerWaits(), "counted after its reply");

    assertTrue(borrowsRightAfterACall(link), "a lone caller reads its reply, however slow the last");
    assertThrows(ExecutionException.class,
        () -> wait.await(link, true, failsAfter(20), System.nanoTime()));
    assertFalse(link.role.callerWaits(), "counted after its deadline");
    assertEquals(0, link.role.parked(), "counted as parked after its deadline");

    link.role.borrow();
    wait.abandon(link, true); // the call could not be sent
    assertFalse(link.role.callerWaits(), "counted after its call was not sent");
  }
}
