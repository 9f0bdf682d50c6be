package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.junit.jupiter.api.Test;

/**
 * Waiting for a reply, spinning or not: the reply arrives however late it comes within the deadline,
 * the deadline holds, a failure reaches the caller, and no outcome leaves the wait counted (a
 * counted caller would stop every later lone caller from spinning).
 */
class ReplyWaitTest {
  private final ReplyWait wait = new ReplyWait();

  @Test
  void aReplyInTimeIsReturnedWhetherItComesDuringTheSpinOrAfter() throws Exception {
    for (long delayMs : new long[] {0, 1, 50}) {
      CompletableFuture<byte[]> reply = new CompletableFuture<>();
      byte[] body = {(byte) delayMs};
      CompletableFuture.delayedExecutor(delayMs, TimeUnit.MILLISECONDS).execute(() -> reply.complete(body));
      long sent = System.nanoTime();
      assertArrayEquals(body, wait.await(reply, sent, sent + TimeUnit.SECONDS.toNanos(5)));
      assertEquals(0, wait.waiting());
    }
  }

  @Test
  void noReplyFailsAtTheDeadline() {
    long sent = System.nanoTime();
    assertThrows(TimeoutException.class, () -> wait.await(new CompletableFuture<>(), sent,
        sent + TimeUnit.MILLISECONDS.toNanos(100)));
    long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - sent);
    assertTrue(waited >= 90, "gave up after " + waited + " ms");
    assertEquals(0, wait.waiting());
  }

  @Test
  void aFailedCallReachesTheCaller() {
    IllegalStateException cause = new IllegalStateException("link lost");
    CompletableFuture<byte[]> reply = CompletableFuture.failedFuture(cause);
    long sent = System.nanoTime();
    ExecutionException e = assertThrows(ExecutionException.class,
        () -> wait.await(reply, sent, sent + TimeUnit.SECONDS.toNanos(5)));
    assertSame(cause, e.getCause());
    assertEquals(0, wait.waiting());
  }
}
