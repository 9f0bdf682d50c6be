package dev.trade.internal.net.mesh;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.IntPredicate;

/**
 * The link states as numbered nodes, so that a route computation walks arrays and bit sets, not
 * hash maps of container ids: with 100 containers every container computes routes many times a
 * second while links come up, and the string lookups were most of its control thread's work.
 *
 * <p>Each node keeps the neighbours its state lists, sorted by id (the order every container walks
 * them in, so that all choose the same shortest paths), and as a bit set for "does it list me
 * back". Numbers are given out as ids are first seen and renumbered when most belong to states
 * that were removed, or to ids that no state lists any more. Not thread-safe: the control thread
 * owns it.
 */
final class Graph {
  private final Map<String, Integer> index = new HashMap<>();
  private final List<String> names = new ArrayList<>();
  private int[][] listed = new int[16][];
  private BitSet[] listedSet = new BitSet[16];
  private int states;
  /** How many neighbours the states list together: with {@link #states}, a bound on live ids. */
  private long edges;
  private int generation;

  /** This node's number, given out now if the id is new. */
  int node(String id) {
    Integer i = index.get(id);
    if (i != null) {
      return i;
    }
    int n = names.size();
    index.put(id, n);
    names.add(id);
    if (n == listed.length) {
      listed = Arrays.copyOf(listed, 2 * n);
      listedSet = Arrays.copyOf(listedSet, 2 * n);
    }
    return n;
  }

  /** The number of {@code id}, or -1 when it has none. */
  int find(String id) {
    Integer i = index.get(id);
    return i == null ? -1 : i;
  }

  String name(int node) {
    return names.get(node);
  }

  /** Nodes numbered so far (some may have no state). */
  int size() {
    return names.size();
  }

  /** Sets the neighbours {@code owner}'s state lists. */
  void put(String owner, Set<String> neighbours) {
    String[] sorted = neighbours.toArray(new String[0]);
    Arrays.sort(sorted);
    int o = node(owner);
    if (listed[o] == null) {
      states++;
    } else {
      edges -= listed[o].length;
    }
    set(o, sorted);
    // Ids that no state lists any more (a neighbour that left before its own state came) are
    // numbered until a renumbering, which forgetting a state alone did not bring about: with links
    // coming and going and no state forgotten, the numbers grew for good.
    if (names.size() > 64 && names.size() > 4 * (states + edges)) {
      renumber();
    }
  }

  private void set(int o, String[] sorted) {
    edges += sorted.length;
    int[] nodes = new int[sorted.length];
    BitSet set = new BitSet();
    for (int i = 0; i < sorted.length; i++) {
      nodes[i] = node(sorted[i]);
      set.set(nodes[i]);
    }
    listed[o] = nodes;
    listedSet[o] = set;
  }

  /** Forgets {@code owner}'s state; renumbers when most numbers are of forgotten states. */
  void remove(String owner) {
    int o = find(owner);
    if (o < 0 || listed[o] == null) {
      return;
    }
    edges -= listed[o].length;
    listed[o] = null;
    listedSet[o] = null;
    states--;
    if (names.size() > 64 && names.size() > 4 * states) {
      renumber();
    }
  }

  /** Counts renumberings: node numbers of different generations do not compare. */
  int generation() {
    return generation;
  }

  private void renumber() {
    generation++;
    Map<String, String[]> kept = new HashMap<>();
    for (int i = 0; i < names.size(); i++) {
      if (listed[i] != null) {
        String[] sorted = new String[listed[i].length];
        for (int k = 0; k < sorted.length; k++) {
          sorted[k] = names.get(listed[i][k]);
        }
        kept.put(names.get(i), sorted);
      }
    }
    index.clear();
    names.clear();
    edges = 0;
    int capacity = Math.max(16, 2 * kept.size());
    listed = new int[capacity][]; // as small as the states kept need: they grow when needed
    listedSet = new BitSet[capacity];
    for (Map.Entry<String, String[]> e : kept.entrySet()) {
      set(node(e.getKey()), e.getValue());
    }
  }

  /**
   * Breadth-first from {@code from} over edges whose both ends list each other, and over every
   * edge {@code from} lists (its own live links, whether or not the peer's state says so yet),
   * neighbours in id order: for each node its distance ({@code -1}: unreachable) and the first hop
   * on its path.
   *
   * @param excluded nodes entered only as direct neighbours of {@code from} (held down: a direct
   *     link proves a container alive)
   */
  void shortestPaths(int from, int[] distance, int[] firstHop, IntPredicate excluded) {
    Arrays.fill(distance, 0, names.size(), -1);
    int[] queue = new int[names.size()];
    int head = 0;
    int tail = 0;
    distance[from] = 0;
    firstHop[from] = from;
    queue[tail++] = from;
    while (head < tail) {
      int at = queue[head++];
      int[] next = listed[at];
      if (next == null) {
        continue;
      }
      for (int n : next) {
        if (distance[n] < 0
            && (at == from || listedSet[n] != null && listedSet[n].get(at) && !excluded.test(n))) {
          distance[n] = distance[at] + 1;
          firstHop[n] = at == from ? n : firstHop[at];
          queue[tail++] = n;
        }
      }
    }
  }
}
