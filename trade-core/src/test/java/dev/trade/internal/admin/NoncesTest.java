package dev.trade.internal.admin;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class NoncesTest {
  @Test
  void refusesReplaysAndProofsOutsideTheWindowOnAFakeClock() {
    Nonces n = new Nonces(30_000, 3);
    long now = 1_000_000;
    assertEquals(Nonces.Verdict.FRESH, n.accept("a", now, now));
    assertEquals(Nonces.Verdict.REPLAYED, n.accept("a", now, now + 29_000));
    assertEquals(Nonces.Verdict.TOO_OLD, n.accept("b", now - 30_001, now));
    assertEquals(Nonces.Verdict.TOO_NEW, n.accept("b", now + 30_001, now));
    assertEquals(Nonces.Verdict.FRESH, n.accept("b", now + 30_000, now));
    assertEquals(Nonces.Verdict.FRESH, n.accept("c", now, now));
    assertEquals(Nonces.Verdict.FULL, n.accept("d", now, now));
    // Once "a" is out of the window it is forgotten; a replay of it is now too old.
    assertEquals(Nonces.Verdict.FRESH, n.accept("d", now + 30_001, now + 30_001));
    assertEquals(3, n.size());
    assertEquals(Nonces.Verdict.TOO_OLD, n.accept("a", now, now + 30_001));
  }
}
