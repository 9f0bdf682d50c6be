package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class TopologyTest {
  private static final long LONG = TimeUnit.SECONDS.toNanos(60);

  @Test
  void shortestPathsUseOnlyEdgesBothEndsList() {
    Topology t = new Topology("me", LONG);
    t.setOwnNeighbours(Set.of("a"));
    t.apply(new Topology.LinkState("a", 1, Set.of("me", "b")));
    assertNull(t.route("b"), "b does not list a back yet");
    t.apply(new Topology.LinkState("b", 1, Set.of("a")));
    assertEquals(new Topology.Route("a", 2), t.route("b"));
    assertEquals(new Topology.Route("a", 1), t.route("a"));
  }

  @Test
  void ownLinksCarryRoutesBeforeThePeersStatesListThem() {
    Topology t = new Topology("me", LONG);
    t.setOwnNeighbours(Set.of("a"));
    assertEquals(new Topology.Route("a", 1), t.route("a"), "a live link of this container's own");
    t.apply(new Topology.LinkState("a", 1, Set.of("b"))); // not me: a's state left before our link
    t.apply(new Topology.LinkState("b", 1, Set.of("a", "c")));
    assertEquals(new Topology.Route("a", 2), t.route("b"));
    t.apply(new Topology.LinkState("c", 1, Set.of()));
    assertNull(t.route("c"), "c does not list b: only this container's own links count one-sided");
  }

  @Test
  void statesShareOneInstanceOfEachId() {
    Topology t = new Topology("me", LONG);
    // As read from frames: equal ids, each a string of its own.
    t.apply(new Topology.LinkState(new String("a"), 1, Set.of(new String("me"), new String("c"))));
    t.apply(new Topology.LinkState(new String("b"), 1, Set.of(new String("c"), new String("a"))));
    t.apply(new Topology.LinkState(new String("a"), 2, Set.of(new String("b"), new String("c"))));
    Topology.LinkState a = t.state("a");
    Topology.LinkState b = t.state("b");
    assertSame(idIn(a.neighbours(), "c"), idIn(b.neighbours(), "c"));
    assertSame(a.owner(), idIn(b.neighbours(), "a"));
    assertSame(b.owner(), idIn(a.neighbours(), "b"));
    assertEquals(Set.of("b", "c"), a.neighbours());
  }

  private static String idIn(Set<String> ids, String id) {
    return ids.stream().filter(id::equals).findFirst().orElseThrow();
  }

  private static Set<String> owners(List<Topology.LinkState> states) {
    Set<String> owners = new HashSet<>();
    states.forEach(s -> owners.add(s.owner()));
    return owners;
  }

  /**
   * c dies, and a no longer reaches b: a's last state of b still lists c. A new neighbour of a is
   * not given the states of containers a lost (a container that restarted after c would reach c
   * through them), and a passes a lost container's state on again once it reaches it again.
   */
  @Test
  void statesOfLostContainersAreNotSharedUntilTheyAreReachableAgain() {
    Topology t = new Topology("a", LONG);
    t.setOwnNeighbours(Set.of("c"));
    t.apply(new Topology.LinkState("c", 1, Set.of("a", "b")));
    t.apply(new Topology.LinkState("b", 1, Set.of("c")));
    t.apply(new Topology.LinkState("far", 1, Set.of("x"))); // never reached: news, shared
    assertEquals(new Topology.Route("c", 2), t.route("b"));
    assertEquals(Set.of("a", "b", "c", "far"), owners(t.statesToShare()));
    t.setOwnNeighbours(Set.of()); // c died
    assertNull(t.route("b"));
    assertEquals(Set.of("a", "far"), owners(t.statesToShare()), "b and c are lost");
    assertEquals(Set.of("a", "b", "c", "far"), owners(t.states()), "still known, for a's own digest");
    assertEquals(List.of(), t.takeRegained());
    t.setOwnNeighbours(Set.of("b")); // a new link to b
    assertEquals(List.of("b"), t.takeRegained(), "b's state is to be passed on again");
    assertEquals(List.of(), t.takeRegained(), "once");
    assertEquals(Set.of("a", "b", "far"), owners(t.statesToShare()));
  }

  /** Link readers drop the copies a flood brings by this check; a pruned state counts as unknown. */
  @Test
  void staleMeansAVersionAppliedAlreadyAndForgetsPrunedStates() {
    Topology t = new Topology("me", LONG);
    assertTrue(t.isStale("me", 5), "own states are never taken from others");
    assertFalse(t.isStale("b", 1));
    t.apply(new Topology.LinkState("b", 2, Set.of("a")));
    assertTrue(t.isStale("b", 1));
    assertTrue(t.isStale("b", 2));
    assertFalse(t.isStale("b", 3));
    t.pruneUnreachable(0, 1); // b is unreachable from now on...
    t.pruneUnreachable(10, 1); // ...and for longer than the grace: forgotten
    assertFalse(t.isStale("b", 2), "a pruned state may be learnt again");
  }

  @Test
  void aStateThatArrivesBeforeItsConnectingStatesIsKept() {
    Topology t = new Topology("me", LONG);
    t.setOwnNeighbours(Set.of("a"));
    t.apply(new Topology.LinkState("b", 1, Set.of("a"))); // b's state first: b not reachable yet
    t.pruneUnreachable(System.nanoTime(), LONG);
    t.apply(new Topology.LinkState("a", 1, Set.of("me", "b")));
    assertEquals(2, t.route("b").distance());
  }

  @Test
  void aContainerThatWentAwayIsNotBroughtBackByAStaleStateButIsByItsOwnNewerOne() {
    Topology t = new Topology("me", LONG);
    t.setOwnNeighbours(Set.of("a", "x"));
    t.apply(new Topology.LinkState("a", 1, Set.of("me")));
    t.apply(new Topology.LinkState("x", 1, Set.of("me", "a")));
    assertNotNull(t.route("x"));
    t.setOwnNeighbours(Set.of("a")); // our link to x died
    assertNull(t.route("x"));
    // a's state from before a noticed x's death arrives late, listing x: x stays away.
    t.apply(new Topology.LinkState("a", 2, Set.of("me", "x")));
    assertNull(t.route("x"));
    assertTrue(t.isHeldDown("x"));
    // x itself says something new: it is alive after all.
    t.apply(new Topology.LinkState("x", 2, Set.of("a")));
    assertEquals(new Topology.Route("a", 2), t.route("x"));
    assertFalse(t.isHeldDown("x"));
  }

  @Test
  void aRemainingPathServesAtOnce() {
    Topology t = new Topology("me", 0);
    t.setOwnNeighbours(Set.of("a", "x"));
    t.apply(new Topology.LinkState("a", 1, Set.of("me", "x")));
    t.apply(new Topology.LinkState("x", 1, Set.of("me", "a")));
    t.setOwnNeighbours(Set.of("a"));
    t.refresh();
    assertEquals(new Topology.Route("a", 2), t.route("x"), "reachable through a once held no more");
  }
}
