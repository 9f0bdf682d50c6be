package dev.trade.internal.net.join;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.net.link.LinkReferee;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/**
 * While a newcomer holds its choice (it has heard few of the containers routing will show it), it
 * dials at once the overlay's choice out of the containers that answered it: before, it lived on
 * one link for up to {@link Finder#HOLD_MAX_INTERVALS} announcement intervals, all of it through a neighbour that, while a
 * large system starts, can be seconds behind. No early link may be one it would not make later.
 */
class FinderEarlyTest {
  /** A newcomer joining a system of random ids, answered by those its overlay chooses. */
  private record Joining(String label, UUID newcomer, Set<UUID> answered, Set<UUID> all) {}

  /** Newcomers to systems of 12, 30, 100 and 300, {@code seeds} systems of each size. */
  private static List<Joining> joinings(int seeds) {
    List<Joining> result = new ArrayList<>();
    for (int n : new int[] {12, 30, 100, 300}) {
      for (long seed = 1; seed <= seeds; seed++) {
        List<UUID> system = new ArrayList<>(OverlayTest.ids(n, seed));
        UUID newcomer = system.remove(0);
        Set<UUID> all = new HashSet<>(system);
        all.add(newcomer);
        result.add(new Joining(n + "/" + seed, newcomer,
            FinderAnswerTest.answering(newcomer, system), all));
      }
    }
    return result;
  }

  @Test
  void theEarlyChoiceIsTheOverlaysChoiceAsFarAsItAnswered() {
    int equal = 0;
    for (Joining j : joinings(25)) {
      Set<UUID> later = Overlay.chosen(j.newcomer(), j.all(), Set.of());
      Set<UUID> early = Finder.early(j.newcomer(), j.answered(), j.answered(), Set.of());
      assertTrue(later.containsAll(early), j.label() + ": " + early + " not in " + later);
      assertTrue(early.containsAll(successors(j.newcomer(), j.all())), j.label());
      equal += early.equals(later) ? 1 : 0;
    }
    assertTrue(equal > 50, equal + " of 100 early choices are the whole choice");
  }

  /**
   * The first container that answers is dialled at once, before the others answer. Where it lies
   * in the interval of a finger, the later choice keeps it as that finger, and the container that
   * answered as that finger is then one link more than the overlay needs: at most one, for a few
   * newcomers in a hundred.
   */
  @Test
  void withTheFirstAnswerLinkedAlreadyAtMostOneEarlyLinkIsOneTooMany() {
    int newcomers = 0;
    int oneTooMany = 0;
    for (Joining j : joinings(50)) {
      for (UUID first : j.answered()) {
        Set<UUID> linked = Set.of(first);
        Set<UUID> extra =
            new HashSet<>(Finder.early(j.newcomer(), j.answered(), j.answered(), linked));
        extra.removeAll(Overlay.chosen(j.newcomer(), j.all(), linked));
        assertTrue(extra.size() <= 1, j.label() + ": " + extra);
        newcomers++;
        oneTooMany += extra.size();
      }
    }
    assertTrue(oneTooMany * 20 < newcomers, oneTooMany + " of " + newcomers);
  }

  @Test
  void containersHeardOnlyFromTheGroupOrForgottenAreNotChosenEarly() {
    List<UUID> system = new ArrayList<>(OverlayTest.ids(100, 7));
    UUID newcomer = system.remove(0);
    Set<UUID> everyone = new HashSet<>(system);
    assertEquals(Set.of(), Finder.early(newcomer, Set.of(), everyone, Set.of()), "no answers");
    Set<UUID> answered = FinderAnswerTest.answering(newcomer, system);
    Set<UUID> stillKnown = new HashSet<>(answered);
    UUID gone = stillKnown.iterator().next();
    stillKnown.remove(gone);
    Set<UUID> early = Finder.early(newcomer, answered, stillKnown, Set.of());
    assertTrue(stillKnown.containsAll(early), early + " has one that is not known any more");
  }

  /** The two containers after {@code self} on the ring of {@code all}. */
  private static Set<UUID> successors(UUID self, Set<UUID> all) {
    List<UUID> ring = new ArrayList<>(all);
    ring.sort(LinkReferee::compareIds);
    int at = ring.indexOf(self);
    return Set.of(ring.get((at + 1) % ring.size()), ring.get((at + 2) % ring.size()));
  }
}
