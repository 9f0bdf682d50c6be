package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** A failure that repeats is logged once, then summarised at most once per interval (fake clock). */
class RepeatedFailuresTest {
  private static final long SECOND = TimeUnit.SECONDS.toNanos(1);
  private final RepeatedFailures<String> failures = new RepeatedFailures<>(60 * SECOND);

  @Test
  void theFirstIsReportedThenOneSummaryPerMinute() {
    long t = 1_000 * SECOND;
    assertEquals(new RepeatedFailures.Report(true, 0, 0), failures.failed("peer", "refused", t));
    for (int i = 1; i < 30; i++) { // a retry every 2 s: silent within the minute
      assertNull(failures.failed("peer", "refused", t + 2 * i * SECOND), "retry " + i);
    }
    assertEquals(new RepeatedFailures.Report(false, 30, 60 * SECOND),
        failures.failed("peer", "refused", t + 60 * SECOND));
    assertNull(failures.failed("peer", "refused", t + 62 * SECOND));
    assertEquals(new RepeatedFailures.Report(false, 2, 61 * SECOND),
        failures.failed("peer", "refused", t + 121 * SECOND));
  }

  @Test
  void aNewTextOrASuccessStartsOver() {
    long t = 5 * SECOND;
    failures.failed("peer", "refused", t);
    assertEquals(new RepeatedFailures.Report(true, 0, 0),
        failures.failed("peer", "timed out", t + SECOND));
    assertNull(failures.failed("peer", "timed out", t + 2 * SECOND));
    failures.succeeded("peer");
    assertEquals(new RepeatedFailures.Report(true, 0, 0),
        failures.failed("peer", "timed out", t + 3 * SECOND));
  }

  @Test
  void eachKeyIsCountedApart() {
    long t = 7 * SECOND;
    failures.failed("a", "refused", t);
    assertEquals(new RepeatedFailures.Report(true, 0, 0), failures.failed("b", "refused", t));
    assertNull(failures.failed("a", "refused", t + SECOND));
  }
}
