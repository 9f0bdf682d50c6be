package dev.trade.internal.net.link;

import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Two links to one container (docs/protocol.md, "Duplicate links"): which one both sides keep, and
 * the loss of a link held while the link that replaces it may be on its way.
 *
 * <p>Each side decides alone which of two links it keeps, and retires the other ({@link #retire})
 * as soon as it has both. The far side may then read the end of the link it had before its own
 * handshake of the kept link is done: for that moment it has no link to the peer. Taken as a
 * loss, that would withdraw the peer's services, fail calls and tell everyone it left, only to
 * take all of it back a few milliseconds later. So a loss is held while a handshake with the same
 * container is under way, until that handshake ends (the new link then took the old one's place,
 * or it failed and the loss stands), and at most one handshake timeout: the id that marks a
 * handshake as the peer's is not proved before the handshake ends, and one who claims it must not
 * hold a loss longer.
 *
 * <p>{@link #begun} is safe on any thread; everything else runs on the network's control thread.
 */
public final class LinkReferee {
  /** A lost link, why, and until when (nanoTime) its loss may be held. */
  public record Held(Link link, String reason, long until) {}

  private final Map<UUID, Held> held = new HashMap<>();
  /**
   * Handshakes under way, by the container id in their peer's HELLO. A count leaves on the control
   * thread, after the task that registers the handshake's link: a loss read before that task and
   * handled before it is held, not taken.
   */
  private final Map<UUID, Integer> handshaking = new ConcurrentHashMap<>();
  private final long holdNanos;
  private final long retireNanos;
  private final ControlScheduler later;

  /**
   * @param holdNanos the longest a loss is held: the handshake timeout
   * @param retireNanos how long a retired link waits for its peer to close it (FAILURETIMEOUT)
   * @param later runs a task on the control thread after a delay
   */
  public LinkReferee(long holdNanos, long retireNanos, ControlScheduler later) {
    this.holdNanos = holdNanos;
    this.retireNanos = retireNanos;
    this.later = later;
  }

  /**
   * Closes a link that another to the same container replaced, in order: says GOODBYE on it and
   * goes on reading it until the peer, which closes it once it has read the GOODBYE, does. So
   * nothing the peer sent over it before is lost: a call made over it is still served, its reply
   * going over the link kept. A peer that has not closed it after {@code retireNanos} has it
   * closed. Nothing else is sent over it after the GOODBYE ({@link Link#retire}).
   */
  public void retire(Link l) {
    try {
      l.retire();
    } catch (IOException e) {
      l.close("duplicate link");
      return;
    }
    later.schedule(() -> l.close("duplicate link: the peer did not close it after GOODBYE"),
        retireNanos);
  }

  /** A handshake with {@code peer} has begun (its HELLO came). Any thread. */
  public void begun(UUID peer) {
    handshaking.merge(peer, 1, Integer::sum);
  }

  /** Whether a handshake with {@code peer} is under way ({@link #begun}, not ended). Any thread. */
  public boolean handshaking(UUID peer) {
    return handshaking.containsKey(peer);
  }

  /** A handshake {@link #begun} told of ended; then call {@link #settle}. */
  public void ended(UUID peer) {
    handshaking.computeIfPresent(peer, (id, n) -> n == 1 ? null : n - 1);
  }

  /**
   * Of the link registered to a container and one just added, the one to close: null when there is
   * no live registered link (the added one takes its place), else as {@link #keepsAdded} decides.
   */
  public static Link toClose(Link existing, Link added, UUID self) {
    if (existing == null || existing.isClosed()) {
      return null;
    }
    return keepsAdded(initiator(existing, self), existing.dial, initiator(added, self), added.dial)
        ? existing : added;
  }

  private static UUID initiator(Link l, UUID self) {
    return l.initiatedHere ? self : l.peerId;
  }

  /**
   * Orders container ids by their 16 bytes as unsigned numbers, the order of RFC 4122 and of other
   * languages' UUID types. Not {@link UUID#compareTo}, which compares signed halves: containers
   * written in another language would then keep a different one of two duplicate links, and place
   * containers differently on the overlay's ring.
   */
  public static int compareIds(UUID a, UUID b) {
    int c = Long.compareUnsigned(a.getMostSignificantBits(), b.getMostSignificantBits());
    return c != 0 ? c : Long.compareUnsigned(a.getLeastSignificantBits(), b.getLeastSignificantBits());
  }

  /**
   * Of two live links to one container, whether the one added last is kept: both sides decide the
   * same, whichever order their handshakes finished in. Dialled by both containers, the link
   * dialled by the one with the smaller id ({@link #compareIds}) is kept; dialled by one (it
   * redialled, or dialled two of the peer's addresses at once), the one it dialled later.
   *
   * @param existingDial the dial numbers of the links ({@link Handshake.Peer#dial}), 0 when the
   *     dialling side did not say; the link added last then counts as the later
   */
  public static boolean keepsAdded(UUID existingInitiator, long existingDial, UUID addedInitiator,
      long addedDial) {
    if (!existingInitiator.equals(addedInitiator)) {
      return compareIds(addedInitiator, existingInitiator) < 0;
    }
    return existingDial == 0 || addedDial == 0 || addedDial > existingDial;
  }

  /**
   * Holds the loss of {@code link}, the registered link to its peer, if a handshake with the peer
   * is under way; false if its loss is to be taken now. Call {@link #settle} when that handshake
   * ends and when the hold runs out ({@link #holdNanos} from now).
   */
  public boolean hold(Link link, String reason, long nowNanos) {
    if (!handshaking.containsKey(link.peerId)) {
      return false;
    }
    // An older hold for the peer is of a link no longer registered: this one replaces it.
    held.put(link.peerId, new Held(link, reason, nowNanos + holdNanos));
    return true;
  }

  public long holdNanos() {
    return holdNanos;
  }

  /**
   * The held loss of the link to {@code peer} if it is to be taken now: no handshake with the peer
   * is under way any more, or the hold ran out. Null if none is held, if it is still held, or if
   * another link has taken its place ({@code current}, the link registered now).
   */
  public Held settle(UUID peer, Link current, long nowNanos) {
    Held h = held.get(peer);
    if (h == null) {
      return null;
    }
    if (current != h.link()) {
      held.remove(peer);
      return null;
    }
    if (handshaking.containsKey(peer) && nowNanos - h.until() < 0) {
      return null;
    }
    held.remove(peer);
    return h;
  }
}
