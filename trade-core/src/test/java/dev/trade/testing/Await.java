package dev.trade.testing;

import java.time.Duration;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;

/**
 * Waits for a condition until a deadline, checking it every millisecond. The only waiting loop of
 * the tests: the deadline is compared as a difference of {@code nanoTime} values, which stays
 * right when the counter overflows, and the timeout is only an upper bound (a test passes as soon
 * as its condition holds, however fast or slow the machine).
 */
public final class Await {
  private Await() {}

  /** @throws AssertionError naming {@code what} if the condition is still false at the deadline */
  public static void until(Duration timeout, BooleanSupplier condition, String what) {
    long deadline = System.nanoTime() + timeout.toNanos();
    while (!condition.getAsBoolean()) {
      if (System.nanoTime() - deadline > 0) {
        throw new AssertionError("timed out after " + timeout.toMillis() + " ms waiting for " + what);
      }
      LockSupport.parkNanos(1_000_000);
    }
  }
}
