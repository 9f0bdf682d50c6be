package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.time.Duration;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Drops authenticated announcements that were heard before or are too old to be current.
 *
 * <p>Two checks, in this order:
 * <ol>
 *   <li><b>Clock:</b> a timestamp more than {@code maxClockSkew} from our clock, either way, is
 *       {@link Reason#CLOCK_SKEW}. This bounds how long a captured packet can be replayed to a
 *       container that has never heard (or has forgotten) its sender. It also rejects every packet
 *       of a host whose clock is off by more than the tolerance, so the log line says "synchronise
 *       the clocks", and {@link Duration#ZERO} turns the check off for hosts that cannot.
 *   <li><b>Sequence:</b> per sender container id, the highest sequence accepted so far; a packet
 *       whose sequence is not above it is dropped. Container ids are unique per incarnation, so a
 *       restarted container starts a new count instead of being taken for a replay. The drop is
 *       {@link Reason#OVERTAKEN} when the sender sent it at most {@link #OVERTAKEN_MILLIS} before
 *       the accepted one (both timestamps are the sender's clock): every start of containers side
 *       by side has a few, since answers and announcements arrive on different sockets and the
 *       receive thread reads them in its own order. Otherwise it is {@link Reason#REPLAYED}.
 * </ol>
 * Memory is bounded: a sender whose newest accepted packet is older than {@code maxClockSkew} is
 * forgotten, since a replay of any of its packets fails the clock check now (so a system whose
 * containers come and go remembers the senders of the last half minute, not every one it heard),
 * unless it is within {@code remember}, which keeps a sender that announces itself less often than
 * the clock tolerance from counting as new at each announcement; and beyond {@code maxSenders} the
 * sender heard from least recently is forgotten (only packets with a valid HMAC get here, so only
 * members of the system can fill the table). A sender forgotten so early passes the sequence check
 * again with its older packets, but not the clock check.
 *
 * <p>Not thread-safe: a {@link Receiver} uses it from its handling only, one datagram at a time.
 */
final class ReplayGuard {
  static final int DEFAULT_MAX_SENDERS = 4096;
  static final Duration DEFAULT_MAX_CLOCK_SKEW = Duration.ofSeconds(30);
  /** How much earlier than the accepted packet a stale one may be sent to count as overtaken. */
  static final long OVERTAKEN_MILLIS = 1000;

  private final long maxSkewMillis;
  /** How long a sender is kept after its newest packet: the tolerance, or longer (remember). */
  private final long keepMillis;
  private final Map<String, Latest> highest;

  /** A guard that keeps senders as long as the clock tolerance (see the other constructor). */
  ReplayGuard(int maxSenders, Duration maxClockSkew) {
    this(maxSenders, maxClockSkew, Duration.ZERO);
  }

  /**
   * @param maxSenders how many senders to remember, at least 1
   * @param maxClockSkew the tolerance either way; zero turns the clock check off
   * @param remember how long at least a sender is kept after its newest accepted packet (a few of
   *     its announcement intervals), if longer than {@code maxClockSkew}
   */
  ReplayGuard(int maxSenders, Duration maxClockSkew, Duration remember) {
    if (maxSenders < 1) {
      throw new IllegalArgumentException("maxSenders " + maxSenders + " < 1");
    }
    if (maxClockSkew.isNegative()) {
      throw new IllegalArgumentException("maxClockSkew " + maxClockSkew + " is negative");
    }
    this.maxSkewMillis = maxClockSkew.toMillis();
    this.keepMillis = Math.max(maxSkewMillis, remember.toMillis());
    // Access order: a sender that keeps announcing is never the one evicted.
    this.highest = new LinkedHashMap<>(64, 0.75f, true) {
      private static final long serialVersionUID = 1L;

      @Override
      protected boolean removeEldestEntry(Map.Entry<String, Latest> eldest) {
        return size() > maxSenders;
      }
    };
  }

  /**
   * Accepts {@code a} and remembers its sequence, or throws without remembering anything.
   *
   * @param nowMillis our clock, ms since the epoch
   * @return whether its sender was not remembered before: new, or forgotten
   * @throws BadPacketException {@link Reason#CLOCK_SKEW} or {@link Reason#REPLAYED}
   */
  boolean check(Announcement a, long nowMillis) throws BadPacketException {
    if (maxSkewMillis > 0) {
      // Both are >= 0 (Announcement checks its timestamp), so the difference cannot overflow.
      long skew = a.timestampMillis() - nowMillis;
      if (Math.abs(skew) > maxSkewMillis) {
        throw new BadPacketException(Reason.CLOCK_SKEW, "timestamp " + Math.abs(skew) + " ms "
            + (skew < 0 ? "behind" : "ahead of") + " our clock (tolerance " + maxSkewMillis
            + " ms): an old packet replayed, or clocks not synchronised");
      }
    }
    Latest last = highest.get(a.containerId());
    if (last != null && a.sequence() <= last.sequence) {
      boolean overtaken = last.timestampMillis - a.timestampMillis() <= OVERTAKEN_MILLIS;
      throw new BadPacketException(overtaken ? Reason.OVERTAKEN : Reason.REPLAYED,
          "sequence " + a.sequence() + " of container '" + a.containerName() + "' ("
          + a.containerId() + "), already at " + last.sequence);
    }
    highest.put(a.containerId(), new Latest(a.sequence(), a.timestampMillis()));
    forgetOutOfClockRange(nowMillis);
    return last == null;
  }

  /**
   * Forgets senders, least recently heard first, while the newest packet of one is older than the
   * clock check lets through (every packet of such a sender fails that check already) and than
   * {@code remember}.
   */
  private void forgetOutOfClockRange(long nowMillis) {
    if (maxSkewMillis == 0) {
      return; // no clock check: the sequence is all that stops a replay
    }
    for (Iterator<Latest> it = highest.values().iterator(); it.hasNext(); ) {
      if (nowMillis - it.next().timestampMillis <= keepMillis) {
        return;
      }
      it.remove();
    }
  }

  /** How many senders are remembered. */
  int size() {
    return highest.size();
  }

  /** The highest sequence accepted from a sender, and when the sender sent it. */
  private record Latest(long sequence, long timestampMillis) {}
}
