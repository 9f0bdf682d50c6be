package dev.trade.internal.net.join;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/**
 * A newcomer is answered by the containers it will dial, not by all: it dials only those, and in
 * a system of 100 every other answer was a packet signed, sent, received and checked for nothing.
 */
class FinderAnswerTest {
  private static List<UUID> members(int n, long seed) {
    return new ArrayList<>(OverlayTest.ids(n, seed)); // random ids, as containers have
  }

  @Test
  void inAFullyMeshedSystemEveryoneAnswers() {
    List<UUID> system = members(Overlay.FULL_MESH_MAX, 1);
    UUID newcomer = system.remove(0);
    for (UUID c : system) {
      Set<UUID> knownToC = new HashSet<>(system);
      knownToC.remove(c);
      assertTrue(Finder.answers(c, newcomer, knownToC), c + " is dialled by the newcomer");
    }
  }

  @Test
  void inALargeSystemExactlyTheContainersTheNewcomerWillDialAnswer() {
    for (long seed = 1; seed <= 5; seed++) {
      List<UUID> system = members(100, seed);
      UUID newcomer = system.remove(0);
      Set<UUID> answering = answering(newcomer, system);
      Set<UUID> all = new HashSet<>(system);
      all.add(newcomer);
      assertEquals(Overlay.chosen(newcomer, all, Set.of()), answering);
      assertTrue(answering.size() <= 8, answering.size() + " answers instead of 99");
    }
  }

  /** The containers of {@code system} that answer {@code newcomer}, each by its own full view. */
  static Set<UUID> answering(UUID newcomer, List<UUID> system) {
    Set<UUID> answering = new HashSet<>();
    for (UUID c : system) {
      Set<UUID> knownToC = new HashSet<>(system);
      knownToC.remove(c);
      if (Finder.answers(c, newcomer, knownToC)) {
        answering.add(c);
      }
    }
    return answering;
  }
}
