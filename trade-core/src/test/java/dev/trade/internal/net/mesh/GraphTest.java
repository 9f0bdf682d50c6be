package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import org.junit.jupiter.api.Test;

/** Route computation over numbered nodes: symmetric edges only, id order, renumbering. */
class GraphTest {
  private static int[] distances(Graph g, String from) {
    int[] distance = new int[g.size()];
    g.shortestPaths(g.node(from), distance, new int[g.size()], node -> false);
    return distance;
  }

  @Test
  void anEdgeCountsOnlyWhenBothEndsListEachOther() {
    Graph g = new Graph();
    g.put("a", Set.of("b"));
    g.put("b", Set.of("a", "c"));
    g.put("c", Set.of()); // c does not list b back
    int[] d = distances(g, "a");
    assertEquals(1, d[g.find("b")]);
    assertEquals(-1, d[g.find("c")]);
  }

  @Test
  void theFirstHopIsTheSmallestIdAmongEqualPaths() {
    Graph g = new Graph();
    g.put("a", Set.of("y", "x"));
    g.put("x", Set.of("a", "z"));
    g.put("y", Set.of("a", "z"));
    g.put("z", Set.of("x", "y"));
    int[] distance = new int[g.size()];
    int[] hop = new int[g.size()];
    g.shortestPaths(g.node("a"), distance, hop, node -> false);
    assertEquals(2, distance[g.find("z")]);
    assertEquals("x", g.name(hop[g.find("z")]));
  }

  @Test
  void forgottenStatesAreRenumberedAwayAndRoutesStay() {
    Graph g = new Graph();
    g.put("a", Set.of("b"));
    g.put("b", Set.of("a"));
    for (int i = 0; i < 200; i++) {
      g.put("gone" + i, Set.of("a"));
    }
    int before = g.generation();
    for (int i = 0; i < 200; i++) {
      g.remove("gone" + i);
    }
    assertTrue(g.generation() > before, "renumbered");
    assertTrue(g.size() < 64, "numbers kept: " + g.size());
    assertEquals(1, distances(g, "a")[g.find("b")]);
  }

  @Test
  void idsNoStateListsAnyMoreAreRenumberedAwayThoughNoStateIsForgotten() {
    Graph g = new Graph();
    g.put("b", Set.of("a"));
    for (int i = 0; i < 10_000; i++) { // neighbours that link and leave before their own state comes
      g.put("a", Set.of("b", "peer" + i));
    }
    assertTrue(g.size() <= 64, "numbers kept: " + g.size());
    assertEquals(1, distances(g, "a")[g.find("b")]);
    assertEquals(1, distances(g, "a")[g.find("peer9999")]);
  }
}
