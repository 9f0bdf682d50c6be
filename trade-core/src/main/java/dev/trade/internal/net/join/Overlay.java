package dev.trade.internal.net.join;

import dev.trade.internal.net.link.LinkReferee;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.UUID;

/**
 * Which of the containers it has heard a container dials: every one of them in a small system, a
 * bounded set in a large one.
 *
 * <p>Up to {@link #FULL_MESH_MAX} containers (this one included), each dials all the others, so
 * that every call takes one hop. Above that, the known containers form a ring ordered by id
 * ({@link LinkReferee#compareIds}, the order every implementation computes the same way), and each
 * container dials its two successors on the ring plus one "finger" in every other interval of
 * the id space ahead of it: [½, 1), [⅛, ¼), [1/32, 1/16) ... of the id space, the odd ones of
 * ⌈log₂ n⌉ such halving intervals. That is at most ⌈⌈log₂ n⌉ / 2⌉ + 2 dialled links per container,
 * and about as many accepted ones. Routes follow shortest paths over all links, dialled and
 * accepted, so paths stay short: containers joining one by one end up 1.7 hops apart on average
 * at 20 containers and 2.5 at 100 (at most 3 and 5), far below the hop limit of 16. A finger in
 * every interval took that to 1.5 and 2.1 hops, but in the scale benchmark's 100-container runs
 * it gave each container about 18.5 links instead of 14.4, and converging took 16 % more CPU:
 * each link is a thread, and each link change a new state flooded over every link. The successor links
 * alone make a ring through every container a container knows, so the links stay connected while
 * views of the membership differ for a moment.
 *
 * <p>A finger is a container this one is linked to already, if one lies in its interval; else one
 * of the interval's containers picked by a hash of this container's id (else, for an empty
 * interval, the first container after it). Containers join one by one and links, once made,
 * stay: choosing by position would move most fingers at every join and leave a trail of links
 * behind, and the hash spreads the fingers of many containers over an interval's members instead
 * of all pointing at its first.
 *
 * <p>Pure functions of their arguments: the same membership and links give the same choice on
 * every container. Thread-safe (stateless).
 */
final class Overlay {
  /** Systems of at most this many containers are fully meshed. */
  static final int FULL_MESH_MAX = 8;
  private static final int SUCCESSORS = 2;

  private Overlay() {}

  /**
   * The containers {@code self} dials, out of {@code members}.
   *
   * @param members every container known, with or without {@code self}
   * @param linked the containers {@code self} has a link to now (kept as fingers where they fit)
   * @return a new set without {@code self}
   */
  static Set<UUID> chosen(UUID self, Collection<UUID> members, Set<UUID> linked) {
    List<UUID> ring = ring(self, members);
    Set<UUID> result = new HashSet<>();
    int n = ring.size();
    if (n <= FULL_MESH_MAX) {
      result.addAll(ring);
    } else {
      int at = ring.indexOf(self);
      for (int k = 1; k <= SUCCESSORS; k++) {
        result.add(ring.get((at + k) % n));
      }
      int intervals = 32 - Integer.numberOfLeadingZeros(n - 1); // ⌈log₂ n⌉, at most 31
      for (int i = 1; i <= intervals; i += 2) {
        result.add(finger(self, ring, i, linked));
      }
    }
    result.remove(self);
    return result;
  }

  /**
   * Whether {@code chooser}, linked to no one yet, dials {@code peer} when it knows {@code members}:
   * {@code chosen(chooser, members, Set.of()).contains(peer)}, computed without sorting the ring or
   * building the choice. Every container runs this for each newcomer it hears (whether to answer
   * it), with the system's whole membership; sorting it each time was 3 % of a scale JVM's CPU.
   *
   * @param members distinct ids (a set's elements), with or without {@code chooser} and {@code peer}
   */
  static boolean chooses(UUID chooser, UUID peer, Collection<UUID> members) {
    UUID[] ids = members.toArray(new UUID[0]);
    boolean hasPeer = false;
    int n = 1; // the ring: ids and chooser
    for (UUID id : ids) {
      if (!id.equals(chooser)) {
        n++;
        hasPeer |= id.equals(peer);
      }
    }
    if (!hasPeer) {
      return false;
    }
    if (n <= FULL_MESH_MAX) {
      return true;
    }
    // A successor: fewer than SUCCESSORS others lie clockwise between chooser and peer.
    int closer = 0;
    for (UUID id : ids) {
      if (!id.equals(chooser) && !id.equals(peer) && ahead(chooser, id, peer)) {
        closer++;
      }
    }
    if (closer < SUCCESSORS) {
      return true;
    }
    int intervals = 32 - Integer.numberOfLeadingZeros(n - 1);
    for (int i = 1; i <= intervals; i += 2) {
      if (isFinger(chooser, peer, ids, i)) {
        return true;
      }
    }
    return false;
  }

  /**
   * Whether {@code peer} is {@code self}'s finger for interval {@code i} ({@link #finger}, linked to
   * none). Going clockwise from the interval's start, the interval's containers are the ids before
   * the first that is outside it (self is, always), and the finger is the one of them at the hashed
   * position; when there are none, the first id from the start, which then lies outside.
   */
  private static boolean isFinger(UUID self, UUID peer, UUID[] ids, int i) {
    UUID from = intervalStart(self, i);
    long width = intervalWidth(i);
    if (!inInterval(peer, self, from, width)) {
      for (UUID id : ids) {
        if (ahead(from, id, peer)) {
          return false; // not the first from the start
        }
      }
      return ahead(from, peer, self);
    }
    UUID firstOut = self;
    for (UUID id : ids) {
      if (!inInterval(id, self, from, width) && ahead(from, id, firstOut)) {
        firstOut = id;
      }
    }
    if (!ahead(from, peer, firstOut)) {
      return false;
    }
    int inside = 0;
    int before = 0; // of them, the ones clockwise from the start before peer
    for (UUID id : ids) {
      if (inInterval(id, self, from, width) && ahead(from, id, firstOut)) {
        inside++;
        if (ahead(from, id, peer)) {
          before++;
        }
      }
    }
    return before == position(self, i, inside);
  }

  /** The condition {@link #finger} stops at: {@code id} is self, or at or beyond the interval's end. */
  private static boolean inInterval(UUID id, UUID self, UUID from, long width) {
    return !id.equals(self)
        && Long.compareUnsigned(id.getMostSignificantBits() - from.getMostSignificantBits(), width) < 0;
  }

  /**
   * Whether {@code a} comes before {@code b} going clockwise round the id space from {@code origin}
   * (an id equal to the origin first of all): their distances from it, as unsigned 128-bit numbers.
   */
  private static boolean ahead(UUID origin, UUID a, UUID b) {
    long oHi = origin.getMostSignificantBits();
    long oLo = origin.getLeastSignificantBits();
    long aLo = a.getLeastSignificantBits() - oLo;
    long aHi = a.getMostSignificantBits() - oHi - (Long.compareUnsigned(a.getLeastSignificantBits(), oLo) < 0 ? 1 : 0);
    long bLo = b.getLeastSignificantBits() - oLo;
    long bHi = b.getMostSignificantBits() - oHi - (Long.compareUnsigned(b.getLeastSignificantBits(), oLo) < 0 ? 1 : 0);
    int c = Long.compareUnsigned(aHi, bHi);
    return c != 0 ? c < 0 : Long.compareUnsigned(aLo, bLo) < 0;
  }

  /** The finger for the interval [2^(128-i), 2^(129-i)) ahead of {@code self}. */
  private static UUID finger(UUID self, List<UUID> ring, int i, Set<UUID> linked) {
    UUID from = intervalStart(self, i);
    long width = intervalWidth(i);
    int first = successorOf(ring, from);
    List<UUID> inside = new ArrayList<>();
    for (int k = first; inside.size() < ring.size(); k = (k + 1) % ring.size()) {
      UUID c = ring.get(k);
      long ahead = c.getMostSignificantBits() - from.getMostSignificantBits();
      if (c.equals(self) || Long.compareUnsigned(ahead, width) >= 0) {
        break;
      }
      if (linked.contains(c)) {
        return c;
      }
      inside.add(c);
    }
    if (inside.isEmpty()) {
      return ring.get(first);
    }
    return inside.get(position(self, i, inside.size()));
  }

  /**
   * The start of the interval [2^(128-i), 2^(129-i)) ahead of {@code self}. Only the high half of an
   * id matters for i <= 64: the bounds' low halves are self's.
   */
  private static UUID intervalStart(UUID self, int i) {
    return new UUID(self.getMostSignificantBits() + intervalWidth(i), self.getLeastSignificantBits());
  }

  /** The width of interval {@code i}, in units of an id's high half. */
  private static long intervalWidth(int i) {
    return 1L << (64 - i);
  }

  /** Which of the {@code size} containers in interval {@code i} is {@code self}'s finger there. */
  private static int position(UUID self, int i, int size) {
    long h = (self.getLeastSignificantBits() ^ self.getMostSignificantBits()) * 0x9E3779B97F4A7C15L + i;
    return (int) Long.remainderUnsigned(h ^ (h >>> 29), size);
  }

  /** The position of the first container at or after {@code point}, cyclically. */
  private static int successorOf(List<UUID> ring, UUID point) {
    int i = Collections.binarySearch(ring, point, LinkReferee::compareIds);
    int at = i >= 0 ? i : -i - 1;
    return at == ring.size() ? 0 : at;
  }

  /** {@code members} and {@code self}, without repeats, in ring order. */
  private static List<UUID> ring(UUID self, Collection<UUID> members) {
    Set<UUID> all = new HashSet<>(members);
    all.add(self);
    List<UUID> ring = new ArrayList<>(all);
    ring.sort(LinkReferee::compareIds);
    return ring;
  }
}
