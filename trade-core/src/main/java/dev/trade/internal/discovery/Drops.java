package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.util.Collections;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counts dropped packets by reason and says why in the log, without flooding it.
 *
 * <p>Every drop is logged at DEBUG. Once per {@code reportIntervalNanos} for each (reason, sender
 * address) pair, a drop is also logged at INFO or WARNING with advice, and with the number of
 * such drops held back since the last report. Our own looped-back packets, and packets overtaken
 * by a later one of the same sender, are only counted: every container hears its own, and every
 * start beside others has a few overtaken ones.
 *
 * <p>{@link #record} is called from one receiver's handling only; {@link #counts()} may be called
 * from any thread.
 */
final class Drops {
  private static final int MAX_REPORTED = 256;

  private final Logger log;
  private final String systemId;
  private final long reportIntervalNanos;
  private final Map<Reason, LongAdder> counts = new EnumMap<>(Reason.class);
  // Confined to the receiver's handling; bounded so that a scan from many addresses cannot grow it.
  private final Map<Source, Report> reports = new LinkedHashMap<>(64, 0.75f, true) {
    private static final long serialVersionUID = 1L;

    @Override
    protected boolean removeEldestEntry(Map.Entry<Source, Report> eldest) {
      return size() > MAX_REPORTED;
    }
  };

  Drops(Logger log, String systemId, long reportIntervalNanos) {
    this.log = log;
    this.systemId = systemId;
    this.reportIntervalNanos = reportIntervalNanos;
    for (Reason r : Reason.values()) {
      counts.put(r, new LongAdder());
    }
  }

  void record(BadPacketException e, InetAddress from, long nowNanos) {
    Reason reason = e.reason();
    counts.get(reason).increment();
    if (log.isLoggable(Level.DEBUG)) {
      log.log(Level.DEBUG, "Dropped a discovery packet from {0} ({1}): {2}",
          from.getHostAddress(), reason, e.getMessage());
    }
    if (reason == Reason.OWN || reason == Reason.OVERTAKEN) {
      return;
    }
    Source key = new Source(reason, from);
    Report r = reports.get(key);
    String suffix = "";
    if (r == null) {
      reports.put(key, new Report(nowNanos));
    } else if (nowNanos - r.lastNanos < reportIntervalNanos) {
      r.held++;
      return;
    } else {
      suffix = r.held == 0 ? "" : " (" + r.held + " more since the last report)";
      r.lastNanos = nowNanos;
      r.held = 0;
    }
    log.log(level(reason), line(e, from) + suffix);
  }

  /** A snapshot with every reason, in declaration order. Unmodifiable. */
  Map<Reason, Long> counts() {
    Map<Reason, Long> snapshot = new EnumMap<>(Reason.class);
    counts.forEach((r, n) -> snapshot.put(r, n.sum()));
    return Collections.unmodifiableMap(snapshot);
  }

  private String line(BadPacketException e, InetAddress from) {
    String who = "Ignoring announcements from " + from.getHostAddress() + ": ";
    switch (e.reason()) {
      case FOREIGN_SYSTEM:
        return who + e.getMessage() + " (this container's is '" + systemId
            + "'); set the same TRADESYSID to join them";
      case BAD_HMAC:
        return who + e.getMessage() + " The system id '" + systemId
            + "' matches, so the sender has other CREDENTIALS, or the packet was forged or damaged";
      case UNSUPPORTED_VERSION:
        return who + e.getMessage() + "; run the same TRADE version everywhere";
      case TOO_SHORT:
      case TOO_LONG:
      case BAD_MAGIC:
        return "Ignoring datagrams from " + from.getHostAddress() + " on the discovery port: "
            + "not TRADE announcements (" + e.getMessage() + "); does another program use it?";
      case CLOCK_SKEW:
        return who + e.getMessage() + "; synchronise the clocks (NTP), or set DISCOVERYCLOCKSKEW";
      case BACKLOG:
        return "Discovery of system '" + systemId + "' fell behind: " + e.getMessage();
      default:
        return who + e.reason().name().toLowerCase(Locale.ROOT) + ": " + e.getMessage();
    }
  }

  private static Level level(Reason reason) {
    switch (reason) {
      case FOREIGN_SYSTEM:
      case TOO_SHORT:
      case TOO_LONG:
      case BAD_MAGIC:
      case REPLAYED:
        return Level.INFO;
      default:
        return Level.WARNING;
    }
  }

  private record Source(Reason reason, InetAddress from) {}

  private static final class Report {
    long lastNanos;
    long held;

    Report(long lastNanos) {
      this.lastNanos = lastNanos;
    }
  }
}
