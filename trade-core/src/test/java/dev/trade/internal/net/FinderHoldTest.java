package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * When a newcomer waits before choosing whom to dial beyond its first contact: until routing (from
 * its first link on) says how many containers there are (it reaches half of those heard) and it
 * has heard nine in ten of them, for at most {@link Finder#HOLD_MAX_NANOS} after its first choice.
 */
class FinderHoldTest {
  private static final long SOON = 100_000_000L;

  @Test
  void waitsWhileRoutingReachesFewerThanHalfOfThoseHeard() {
    assertTrue(Finder.holds(SOON, 5, 0), "no link up yet");
    assertTrue(Finder.holds(SOON, 30, 2), "the first link's states not applied yet");
    assertTrue(Finder.holds(SOON, 30, 14));
    assertFalse(Finder.holds(SOON, 9, 8), "one heard that has just started, not linked yet");
    assertFalse(Finder.holds(SOON, 30, 28));
  }

  @Test
  void waitsUntilNineInTenAreHeard() {
    assertTrue(Finder.holds(SOON, 10, 99), "10 of 99 heard");
    assertTrue(Finder.holds(SOON, 89, 99), "89 of 99 heard");
    assertFalse(Finder.holds(SOON, 90, 99), "90 of 99 heard");
    assertFalse(Finder.holds(SOON, 99, 99), "all heard");
    assertFalse(Finder.holds(SOON, 3, 3), "a small system, all heard");
  }

  @Test
  void waitsNoLongerThanTheLimitSinceTheFirstChoice() {
    // Containers beyond a bridging container are reached but never heard.
    assertTrue(Finder.holds(Finder.HOLD_MAX_NANOS - 1, 10, 99));
    assertFalse(Finder.holds(Finder.HOLD_MAX_NANOS, 10, 99));
    assertFalse(Finder.holds(Finder.HOLD_MAX_NANOS, 30, 2));
  }

  @Test
  void aContainerThatHeardOneHasNothingToWaitFor() {
    assertFalse(Finder.holds(SOON, 1, 0));
    assertFalse(Finder.holds(SOON, 1, 50));
    assertFalse(Finder.holds(SOON, 0, 0));
  }
}
