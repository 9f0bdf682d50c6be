package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

class ReplayGuardTest {
  private static final long NOW = 1_700_000_000_000L;
  private final ReplayGuard guard = new ReplayGuard(4096, Duration.ofSeconds(30));

  @Test
  void acceptsGrowingSequencesAndRejectsRepeatsAndOlderOnes() throws BadPacketException {
    assertTrue(guard.check(at("a", 5, NOW - 5000), NOW));
    assertFalse(guard.check(at("a", 6, NOW), NOW));
    assertEquals("sequence 6 of container 'name-a' (a), already at 6",
        rejected(Reason.OVERTAKEN, at("a", 6, NOW)).getMessage());
    assertEquals("sequence 5 of container 'name-a' (a), already at 6",
        rejected(Reason.REPLAYED, at("a", 5, NOW - 5000)).getMessage());
    assertTrue(guard.check(at("b", 1, NOW), NOW), "senders are counted separately");
  }

  @Test
  void aStalePacketSentWithinASecondOfTheAcceptedOneWasOvertakenNotReplayed()
      throws BadPacketException {
    guard.check(at("a", 7, NOW), NOW);
    rejected(Reason.OVERTAKEN, at("a", 6, NOW - ReplayGuard.OVERTAKEN_MILLIS));
    rejected(Reason.REPLAYED, at("a", 6, NOW - ReplayGuard.OVERTAKEN_MILLIS - 1));
    rejected(Reason.OVERTAKEN, at("a", 7, NOW), "delivered twice");
    guard.check(at("a", 8, NOW + 10), NOW);
    rejected(Reason.REPLAYED, at("a", 1, NOW - 20_000));
  }

  @Test
  void rejectsTimestampsBeyondTheToleranceEitherWay() throws BadPacketException {
    assertEquals("timestamp 30001 ms behind our clock (tolerance 30000 ms): an old packet"
        + " replayed, or clocks not synchronised",
        rejected(Reason.CLOCK_SKEW, at("a", 1, NOW - 30_001)).getMessage());
    rejected(Reason.CLOCK_SKEW, at("a", 1, NOW + 30_001));
    guard.check(at("a", 1, NOW - 30_000), NOW);
    guard.check(at("a", 2, NOW + 30_000), NOW);
  }

  @Test
  void aRejectedPacketLeavesNoTrace() throws BadPacketException {
    rejected(Reason.CLOCK_SKEW, at("a", 9, NOW - 60_000));
    assertEquals(0, guard.size());
    assertTrue(guard.check(at("a", 1, NOW), NOW));
  }

  @Test
  void zeroToleranceTurnsTheClockCheckOff() throws BadPacketException {
    ReplayGuard unsynced = new ReplayGuard(10, Duration.ZERO);
    unsynced.check(at("a", 1, 0), NOW);
    unsynced.check(at("a", 2, NOW * 2), NOW);
  }

  @Test
  void forgetsTheSenderHeardLeastRecentlyBeyondTheBound() throws BadPacketException {
    ReplayGuard small = new ReplayGuard(2, Duration.ofSeconds(30));
    small.check(at("a", 5, NOW), NOW);
    small.check(at("b", 5, NOW), NOW);
    small.check(at("a", 6, NOW), NOW); // a is now the most recent
    small.check(at("c", 5, NOW), NOW); // evicts b
    assertEquals(2, small.size());
    assertThrows(BadPacketException.class, () -> small.check(at("a", 6, NOW), NOW));
    assertTrue(small.check(at("b", 1, NOW), NOW), "b was forgotten, so it is new again");
  }

  @Test
  void forgetsSendersWhosePacketsAllFailTheClockCheckNow() throws BadPacketException {
    guard.check(at("gone", 5, NOW), NOW);
    guard.check(at("stays", 5, NOW), NOW);
    long later = NOW + 30_001;
    guard.check(at("stays", 6, later - 1_000), later); // heard again meanwhile
    guard.check(at("new", 1, later), later);
    assertEquals(2, guard.size(), "'gone' was last heard more than 30 s ago");
    assertEquals(Reason.CLOCK_SKEW, assertThrows(BadPacketException.class,
        () -> guard.check(at("gone", 5, NOW), later)).reason(), "its replay fails the clock check");
    assertThrows(BadPacketException.class, () -> guard.check(at("stays", 6, later), later));
  }

  @Test
  void aSenderThatAnnouncesLessOftenThanTheToleranceStaysKnownForItsIntervals()
      throws BadPacketException {
    // BROADCASTINTERVAL 20 s, remembered for three of them, beside the 30 s clock tolerance.
    ReplayGuard slow = new ReplayGuard(4096, Duration.ofSeconds(30), Duration.ofSeconds(60));
    assertTrue(slow.check(at("slow", 1, NOW), NOW));
    slow.check(at("other", 1, NOW + 40_000), NOW + 40_000);
    assertFalse(slow.check(at("slow", 2, NOW + 40_000), NOW + 40_000),
        "its next announcement, 40 s later, is not a newcomer's");
    slow.check(at("other", 2, NOW + 101_000), NOW + 101_000);
    assertEquals(1, slow.size(), "forgotten once silent for longer than both");
  }

  @Test
  void discoveryKeepsASenderForThreeOfItsIntervals() throws BadPacketException {
    // Announcing every 20 s with the default 30 s clock tolerance.
    ReplayGuard g = Discovery.replayGuard(Discovery.builder().interval(Duration.ofSeconds(20)));
    assertTrue(g.check(at("slow", 1, NOW), NOW));
    g.check(at("other", 1, NOW + 40_000), NOW + 40_000);
    assertFalse(g.check(at("slow", 2, NOW + 40_000), NOW + 40_000));
  }

  @Test
  void withoutTheClockCheckOnlyTheBoundForgets() throws BadPacketException {
    ReplayGuard unsynced = new ReplayGuard(10, Duration.ZERO);
    unsynced.check(at("a", 5, NOW), NOW);
    unsynced.check(at("b", 5, NOW + 3_600_000), NOW + 3_600_000);
    assertEquals(2, unsynced.size());
    assertThrows(BadPacketException.class, () -> unsynced.check(at("a", 5, NOW), NOW + 3_600_000),
        "a replay an hour later is still refused by its sequence");
  }

  private BadPacketException rejected(Reason reason, Announcement a) {
    return rejected(reason, a, "");
  }

  private BadPacketException rejected(Reason reason, Announcement a, String why) {
    BadPacketException e = assertThrows(BadPacketException.class, () -> guard.check(a, NOW), why);
    assertEquals(reason, e.reason(), why);
    return e;
  }

  private static Announcement at(String id, long sequence, long timestamp) {
    return new Announcement(1, "s", id, "name-" + id, List.of(), sequence, timestamp);
  }
}
