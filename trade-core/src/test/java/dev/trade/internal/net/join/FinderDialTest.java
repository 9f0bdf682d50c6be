package dev.trade.internal.net.join;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/**
 * Of two containers that choose each other, only the one with the smaller id dials at once (the
 * other waits for its link): two dials made two links, and closing one as a duplicate could reach
 * the other side before the link that stays, which then saw its peer leave and join again.
 */
class FinderDialTest {
  private final UUID low = new UUID(1, 0);
  private final UUID high = new UUID(2, 0);

  @Test
  void ofTwoContainersAloneOnlyTheSmallerIdDialsAtOnce() {
    assertTrue(Finder.dialsAtOnce(low, high, Set.of(high)));
    assertFalse(Finder.dialsAtOnce(high, low, Set.of(low)), "low dials high: high waits");
  }

  @Test
  void inALargeSystemEachPairThatChoosesEachOtherDialsOnce() {
    List<UUID> members = new ArrayList<>();
    for (long i = 1; i <= 40; i++) {
      members.add(new UUID(i * 0x0123_4567_89AB_CDEFL, i));
    }
    int mutual = 0;
    for (UUID a : members) {
      Set<UUID> knownToA = new HashSet<>(members);
      knownToA.remove(a);
      for (UUID b : Overlay.chosen(a, members, Set.of())) {
        Set<UUID> knownToB = new HashSet<>(members);
        knownToB.remove(b);
        boolean aDials = Finder.dialsAtOnce(a, b, knownToA);
        if (Overlay.chosen(b, members, Set.of()).contains(a)) {
          mutual++;
          boolean bDials = Finder.dialsAtOnce(b, a, knownToB);
          assertEquals(1, (aDials ? 1 : 0) + (bDials ? 1 : 0), a + " and " + b + " choose each other");
        } else {
          assertTrue(aDials, b + " does not choose " + a + ": nobody else would dial");
        }
      }
    }
    assertTrue(mutual > 0, "the membership has pairs that choose each other");
  }
}
