package dev.trade.internal.lock;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** When a call that waits for a lock gives up, as a function of its deadline and now. */
class LockLinkTest {
  private static final long MS = 1_000_000L;

  @Test
  void aWaitingCallKeepsAQuarterOfItsTimeAtMostHalfASecondForTheRefusal() {
    assertEquals(750 * MS, LockLink.waitDeadline(1000 * MS, 0), "a quarter of 1 s");
    assertEquals(9500 * MS, LockLink.waitDeadline(10_000 * MS, 0), "at most 0.5 s of 10 s");
    assertEquals(100 * MS + 75 * MS, LockLink.waitDeadline(200 * MS, 100 * MS), "from now");
    assertEquals(5 * MS, LockLink.waitDeadline(5 * MS, 9 * MS), "past its deadline: at once");
    assertEquals(Long.MIN_VALUE + 750 * MS,
        LockLink.waitDeadline(Long.MIN_VALUE + 1000 * MS, Long.MIN_VALUE), "nanoTime wraps");
  }
}
