package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A link's round-trip time from probes and echoes, at times the test passes. */
class RoundTripTest {
  private static final long US = 1_000L;
  private static final long T = 5_000_000_000L;

  @Test
  void theEstimateIsTheMeanOfTheFirstEightSamplesThenMovesByAnEighth() {
    RoundTrip rtt = new RoundTrip(T);
    assertEquals(RoundTrip.UNKNOWN, rtt.nanos(), "nothing measured yet");
    echo(rtt, 1, 8_400 * US); // the first, as the link came up in a JVM still starting
    assertEquals(8_400 * US, rtt.nanos());
    echo(rtt, 2, 400 * US);
    assertEquals(4_400 * US, rtt.nanos(), "the mean of two");
    for (int i = 3; i <= 8; i++) {
      echo(rtt, i, 400 * US);
    }
    assertEquals(1_400 * US, rtt.nanos(), "the mean of 8: the first counts 1/8, not for good");
    echo(rtt, 9, 1_400 * US + 800 * US); // one slow echo
    assertEquals(1_500 * US, rtt.nanos(), "7/8 of the estimate + 1/8 of the sample");
  }

  /** Probe {@code n} (one a second) is echoed after {@code took}. */
  private static void echo(RoundTrip rtt, int n, long took) {
    long sent = T + n * 1_000_000 * US;
    assertTrue(rtt.echoed(rtt.sent(sent), sent + took));
  }

  @Test
  void anEchoOfAnythingButTheOutstandingProbeIsIgnored() {
    RoundTrip rtt = new RoundTrip(T);
    assertFalse(rtt.echoed(T, T + 10 * US), "no probe was sent");
    long first = rtt.sent(T + 100 * US);
    long second = rtt.sent(T + 200 * US); // the first was never echoed: an older peer, say
    assertFalse(rtt.echoed(first, T + 300 * US), "an old probe's echo");
    assertFalse(rtt.echoed(second + 1, T + 300 * US), "a token never sent");
    assertEquals(RoundTrip.UNKNOWN, rtt.nanos());
    assertTrue(rtt.echoed(second, T + 300 * US));
    assertEquals(100 * US, rtt.nanos());
    assertFalse(rtt.echoed(second, T + 900 * US), "the same echo twice counts once");
    assertEquals(100 * US, rtt.nanos());
  }

  @Test
  void aProbeIsDueEveryPeriodFromTheLinksStartWhetherOrNotEchoed() {
    long every = 10_000 * US;
    RoundTrip rtt = new RoundTrip(T);
    assertFalse(rtt.due(T + every - 1, every));
    assertTrue(rtt.due(T + every, every));
    rtt.sent(T + every);
    assertFalse(rtt.due(T + 2 * every - 1, every), "one just left, unanswered");
    assertTrue(rtt.due(T + 2 * every, every), "an echo that never comes holds nothing up");
  }
}
