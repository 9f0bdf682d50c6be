package dev.trade.internal.net.join;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.net.link.LinkReferee;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.Random;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/** Which containers a container dials ({@link Overlay}). */
class OverlayTest {
  static List<UUID> ids(int n, long seed) {
    Random r = new Random(seed);
    List<UUID> result = new ArrayList<>();
    for (int i = 0; i < n; i++) {
      result.add(new UUID(r.nextLong(), r.nextLong()));
    }
    return result;
  }

  /** Undirected links: every container's choice out of its own view, both directions. */
  private static Map<UUID, Set<UUID>> links(Map<UUID, List<UUID>> views) {
    Map<UUID, Set<UUID>> g = new HashMap<>();
    views.forEach((self, view) -> {
      g.computeIfAbsent(self, k -> new HashSet<>());
      for (UUID peer : Overlay.chosen(self, view, Set.of())) {
        g.get(self).add(peer);
        g.computeIfAbsent(peer, k -> new HashSet<>()).add(self);
      }
    });
    return g;
  }

  private static Map<UUID, List<UUID>> sameView(List<UUID> members) {
    Map<UUID, List<UUID>> views = new HashMap<>();
    for (UUID m : members) {
      views.put(m, members);
    }
    return views;
  }

  /** The largest number of hops from {@code from} to any container, or -1 if one is unreachable. */
  private static int eccentricity(Map<UUID, Set<UUID>> g, UUID from) {
    Map<UUID, Integer> hops = hops(g, from);
    return hops.size() == g.size() ? hops.values().stream().max(Integer::compare).orElse(0) : -1;
  }

  /** The links from {@code from} to every container it reaches, by shortest paths. */
  private static Map<UUID, Integer> hops(Map<UUID, Set<UUID>> g, UUID from) {
    Map<UUID, Integer> hops = new HashMap<>(Map.of(from, 0));
    Queue<UUID> queue = new ArrayDeque<>(List.of(from));
    while (!queue.isEmpty()) {
      UUID at = queue.poll();
      for (UUID n : g.get(at)) {
        if (!hops.containsKey(n)) {
          hops.put(n, hops.get(at) + 1);
          queue.add(n);
        }
      }
    }
    return hops;
  }

  private static int log2Ceil(int n) {
    return 32 - Integer.numberOfLeadingZeros(n - 1);
  }

  @Test
  void smallSystemsAreFullyMeshed() {
    for (int n = 1; n <= Overlay.FULL_MESH_MAX; n++) {
      List<UUID> members = ids(n, n);
      for (UUID self : members) {
        Set<UUID> expected = new HashSet<>(members);
        expected.remove(self);
        assertEquals(expected, Overlay.chosen(self, members, Set.of()), n + " containers");
      }
    }
  }

  @Test
  void theChoiceDependsOnlyOnTheMembershipAndEveryoneComputesTheSame() {
    List<UUID> members = ids(40, 7);
    List<UUID> shuffled = new ArrayList<>(members);
    Collections.shuffle(shuffled, new Random(3));
    List<UUID> withoutSelf = new ArrayList<>(members);
    for (UUID self : members) {
      withoutSelf.remove(self);
      Set<UUID> chosen = Overlay.chosen(self, members, Set.of());
      assertEquals(chosen, Overlay.chosen(self, shuffled, Set.of()));
      assertEquals(chosen, Overlay.chosen(self, withoutSelf, Set.of()), "self in the view or not");
      withoutSelf.add(self);
      for (UUID peer : members) {
        assertEquals(chosen.contains(peer), Overlay.chooses(self, peer, members),
            "what another container predicts about " + self + " and " + peer);
      }
    }
  }

  /**
   * {@link Overlay#chooses} computes without sorting what {@link Overlay#chosen} computes by
   * sorting the ring: compared over random systems and over ids placed where the rule's edges
   * are, on the interval bounds of a chooser (the same high half with a smaller or larger low
   * half), clustered in one interval, and equal in their high halves.
   */
  @Test
  void choosesAgreesWithTheChoiceItPredicts() {
    Random r = new Random(11);
    int compared = 0;
    for (int system = 0; system < 300; system++) {
      int n = system < 100 ? 1 + system % 20 : 9 + r.nextInt(system < 280 ? 60 : 200);
      List<UUID> members = ids(n, r.nextLong());
      UUID anchor = members.get(0);
      for (int k = 0; k < n / 3; k++) {
        int i = 1 + r.nextInt(8);
        long bound = anchor.getMostSignificantBits() + (1L << (64 - i)) + r.nextInt(3) - 1;
        long low = anchor.getLeastSignificantBits() + r.nextInt(3) - 1;
        switch (r.nextInt(4)) {
          case 0 -> members.add(new UUID(bound, low)); // on an interval's start
          case 1 -> members.add(new UUID(bound + (1L << (63 - i)), r.nextLong())); // inside one
          case 2 -> members.add(new UUID(anchor.getMostSignificantBits(), r.nextLong()));
          default -> members.add(new UUID(r.nextLong() >>> 60 << 60, r.nextLong()));
        }
      }
      List<UUID> distinct = new ArrayList<>(new HashSet<>(members));
      Collections.shuffle(distinct, r);
      UUID outsider = new UUID(r.nextLong(), r.nextLong());
      for (UUID chooser : distinct.subList(0, Math.min(distinct.size(), 12))) {
        List<UUID> withoutChooser = new ArrayList<>(distinct);
        withoutChooser.remove(chooser);
        Set<UUID> chosen = Overlay.chosen(chooser, distinct, Set.of());
        for (UUID peer : distinct) {
          assertEquals(chosen.contains(peer), Overlay.chooses(chooser, peer, distinct),
              chooser + " choosing " + peer + " out of " + distinct);
          assertEquals(chosen.contains(peer), Overlay.chooses(chooser, peer, withoutChooser),
              chooser + " choosing " + peer + " out of the others " + withoutChooser);
          compared++;
        }
        assertFalse(Overlay.chooses(chooser, outsider, distinct), "not a member");
      }
    }
    assertTrue(compared > 20_000, "compared " + compared);
  }

  @Test
  void largeSystemsHaveLogarithmicDegreeAndDiameterAndAreConnected() {
    for (int n : new int[] {9, 10, 17, 30, 64, 100, 333, 1000}) {
      List<UUID> members = ids(n, n);
      Map<UUID, Set<UUID>> g = links(sameView(members));
      int log = log2Ceil(n);
      int most = 0;
      for (UUID m : members) {
        assertTrue(Overlay.chosen(m, members, Set.of()).size() <= (log + 1) / 2 + 2,
            n + ": dials at most log2 n / 2 + 2");
        most = Math.max(most, g.get(m).size());
      }
      // About log2 n / 2 dialled and as many accepted; the ids' random spacing skews the accepted.
      assertTrue(most <= 4 * log, n + ": " + most + " links, more than 4 log2 n");
      // Diameter: every container reaches every other within log2 n hops (16 is the hop limit).
      for (UUID m : members.subList(0, Math.min(n, 50))) {
        int e = eccentricity(g, m);
        assertTrue(e >= 0, n + ": not connected");
        assertTrue(e <= log, n + ": " + e + " hops, more than log2 n");
      }
      System.out.println(n + " containers: at most " + most + " links");
    }
  }

  @Test
  void theLinksStayConnectedWhenViewsDiffer() {
    // Two subnets that only a bridge hears both of (the multihost system test, at scale): each side
    // sees itself and the bridge, the bridge sees everyone.
    List<UUID> a = ids(30, 1);
    List<UUID> b = ids(30, 2);
    UUID bridge = new UUID(0, 42);
    Map<UUID, List<UUID>> views = new HashMap<>();
    List<UUID> viewA = new ArrayList<>(a);
    viewA.add(bridge);
    List<UUID> viewB = new ArrayList<>(b);
    viewB.add(bridge);
    List<UUID> all = new ArrayList<>(viewA);
    all.addAll(b);
    a.forEach(m -> views.put(m, viewA));
    b.forEach(m -> views.put(m, viewB));
    views.put(bridge, all);
    assertTrue(eccentricity(links(views), bridge) >= 0, "bridged subnets not connected");

    // Views that grow in different orders at start-up: each container knows a different part.
    List<UUID> members = ids(60, 5);
    Random r = new Random(9);
    Map<UUID, List<UUID>> partial = new HashMap<>();
    for (UUID m : members) {
      List<UUID> view = new ArrayList<>();
      for (UUID other : members) {
        if (r.nextInt(10) != 0) { // each misses a tenth of the others
          view.add(other);
        }
      }
      partial.put(m, view);
    }
    assertTrue(eccentricity(links(partial), members.get(0)) >= 0, "partial views not connected");
  }

  @Test
  void containersJoiningOneByOneLeaveFewExtraLinks() {
    // Links are never closed for the overlay's sake: what every container chose at any moment of
    // the growth stays. Each chooses again at every join, knowing its links.
    int n = 100;
    List<UUID> members = ids(n, 21);
    Map<UUID, Set<UUID>> g = new HashMap<>();
    members.forEach(m -> g.put(m, new HashSet<>()));
    for (int k = 1; k <= n; k++) {
      List<UUID> view = members.subList(0, k);
      for (UUID self : view) {
        for (UUID peer : Overlay.chosen(self, view, Set.copyOf(g.get(self)))) {
          g.get(self).add(peer);
          g.get(peer).add(self);
        }
      }
    }
    int total = 0;
    int most = 0;
    for (Set<UUID> links : g.values()) {
      total += links.size();
      most = Math.max(most, links.size());
    }
    double mean = total / (double) n;
    long pathSum = 0;
    for (UUID m : members) {
      pathSum += hops(g, m).values().stream().mapToInt(Integer::intValue).sum();
    }
    double meanPath = pathSum / (double) (n * (n - 1));
    System.out.println("grown one by one: " + mean + " links on average, at most " + most
        + "; paths of " + meanPath + " links on average");
    // Fewer links make longer paths: half a link more on average than with a finger per interval.
    assertTrue(meanPath <= 3, meanPath + " links on the average path");
    // Each link is a thread at both ends, and each link change a state flooded over every link.
    assertTrue(mean <= 2 * ((log2Ceil(n) + 1) / 2 + 2), mean + " links on average");
    assertTrue(most <= n / 2, most + " links");
  }

  @Test
  void aLinkedContainerStaysAFingerWhenOthersJoin() {
    List<UUID> members = new ArrayList<>(ids(20, 31));
    members.sort(LinkReferee::compareIds);
    UUID self = members.get(0);
    Set<UUID> chosen = Overlay.chosen(self, members, Set.of());
    List<UUID> small = new ArrayList<>(members);
    small.sort(LinkReferee::compareIds);
    chosen.remove(small.get(1)); // self's successors then: not fingers
    chosen.remove(small.get(2));
    List<UUID> grown = new ArrayList<>(members);
    grown.addAll(ids(20, 32));
    Set<UUID> again = Overlay.chosen(self, grown, chosen);
    List<UUID> ring = new ArrayList<>(grown);
    ring.sort(LinkReferee::compareIds);
    int at = ring.indexOf(self);
    Set<UUID> successors = Set.of(ring.get((at + 1) % 40), ring.get((at + 2) % 40));
    for (UUID c : chosen) {
      if (!successors.contains(c) && !again.contains(c)) {
        // Only a finger whose interval split in two (one more finger for 40 than for 20) may move.
        assertTrue(again.size() > chosen.size(), c + " dropped");
      }
    }
    assertEquals(again, Overlay.chosen(self, grown, chosen), "deterministic given the links");
  }

  @Test
  void theRingFormsAgainWhenAContainerLeaves() {
    List<UUID> members = ids(50, 11);
    List<UUID> ring = new ArrayList<>(members);
    ring.sort(LinkReferee::compareIds);
    UUID before = ring.get(9);
    UUID gone = ring.get(10);
    UUID after = ring.get(11);
    assertTrue(Overlay.chosen(before, members, Set.of()).contains(gone), "its successor");

    List<UUID> survivors = new ArrayList<>(members);
    survivors.remove(gone);
    assertTrue(Overlay.chosen(before, survivors, Set.of()).contains(after), "the new successor");
    for (UUID m : survivors) {
      assertFalse(Overlay.chosen(m, survivors, Set.of()).contains(gone));
    }
    Map<UUID, Set<UUID>> g = links(sameView(survivors));
    assertFalse(g.containsKey(gone));
    assertTrue(eccentricity(g, before) >= 0, "survivors not connected");
  }
}
