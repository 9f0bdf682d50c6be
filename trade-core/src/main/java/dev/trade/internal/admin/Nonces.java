package dev.trade.internal.admin;

import java.util.ArrayDeque;
import java.util.HashSet;
import java.util.Set;

/**
 * Refuses replayed proofs: a proof's time must be within {@code windowMillis} of this container's
 * clock either way, and its nonce must not have been accepted before. A nonce is remembered until
 * its time falls out of the window, when the clock check refuses a replay anyway; so memory holds
 * at most the proofs of one window, and beyond {@code max} of them new proofs are refused (only
 * proofs with a valid MAC get here, so only principals can fill it). Time is a parameter.
 * Thread-safe: one lock.
 */
final class Nonces {
  enum Verdict { FRESH, TOO_OLD, TOO_NEW, REPLAYED, FULL }

  private record Seen(String nonce, long timeMillis) {}

  private final long windowMillis;
  private final int max;
  // Guarded by this: nonces in order of arrival; removed once their time is out of the window.
  private final ArrayDeque<Seen> order = new ArrayDeque<>();
  private final Set<String> seen = new HashSet<>();

  Nonces(long windowMillis, int max) {
    this.windowMillis = windowMillis;
    this.max = max;
  }

  /** Checks and, when fresh, remembers a proof's nonce; {@code nowMillis} is this clock. */
  synchronized Verdict accept(String nonce, long timeMillis, long nowMillis) {
    if (timeMillis < nowMillis - windowMillis) {
      return Verdict.TOO_OLD;
    }
    if (timeMillis > nowMillis + windowMillis) {
      return Verdict.TOO_NEW;
    }
    forget(nowMillis);
    if (seen.contains(nonce)) {
      return Verdict.REPLAYED;
    }
    if (seen.size() >= max) {
      return Verdict.FULL;
    }
    seen.add(nonce);
    order.add(new Seen(nonce, timeMillis));
    return Verdict.FRESH;
  }

  /** Forgets nonces whose time is out of the window (a replay of them is TOO_OLD now). */
  private void forget(long nowMillis) {
    // Arrival order is close to time order (within the window): a nonce whose time is older than
    // one ahead of it is forgotten at most one window late, which only delays its release.
    while (!order.isEmpty() && order.peekFirst().timeMillis() < nowMillis - windowMillis) {
      seen.remove(order.pollFirst().nonce());
    }
  }

  long windowMillis() {
    return windowMillis;
  }

  synchronized int size() {
    return seen.size();
  }
}
