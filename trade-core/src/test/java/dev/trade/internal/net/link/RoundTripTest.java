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
  void theFirstEchoIsTheEstimateAndLaterOnesMoveItByAnEighth() {
    RoundTrip rtt = new RoundTrip(T);
    assertEquals(RoundTrip.UNKNOWN, rtt.nanos(), "nothing measured yet");
    long token = rtt.sent(T + 1_000 * US);
    assertTrue(rtt.echoed(token, T + 1_400 * US));
    assertEquals(400 * US, rtt.nanos());
    token = rtt.sent(T + 2_000 * US);
    assertTrue(rtt.echoed(token, T + 3_200 * US)); // one slow echo of 1200 µs
    assertEquals(400 * US - 50 * US + 150 * US, rtt.nanos(), "7/8 of 400 µs + 1/8 of 1200 µs");
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
