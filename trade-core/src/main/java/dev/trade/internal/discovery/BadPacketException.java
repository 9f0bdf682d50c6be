package dev.trade.internal.discovery;

import java.util.Objects;

/**
 * A datagram on the discovery port that is not an announcement we may act on, with the reason.
 *
 * <p>Thrown while a packet is checked; {@link Discovery} never lets it escape: it counts the packet
 * under its {@link #reason()} and logs it. The message never contains credentials or key material;
 * text taken from the packet is quoted and stripped of control characters.
 */
public final class BadPacketException extends Exception {
  private static final long serialVersionUID = 1L;

  /**
   * Why a packet was dropped, in the order the checks run: the cheap, unauthenticated header checks
   * first, then the HMAC, and only then the fields it protects.
   */
  public enum Reason {
    /** Shorter than the smallest possible announcement, or than its own header plus the HMAC. */
    TOO_SHORT,
    /** Longer than 1200 bytes (see {@code docs/discovery.md}). */
    TOO_LONG,
    /** Does not start with the magic bytes: not a TRADE announcement at all. */
    BAD_MAGIC,
    /** A TRADE announcement of a protocol version this container does not speak. */
    UNSUPPORTED_VERSION,
    /** A TRADE announcement of another system id (checked before the HMAC, so that logs say so). */
    FOREIGN_SYSTEM,
    /** Our system id, but the HMAC does not match: wrong credentials, or forged or corrupted. */
    BAD_HMAC,
    /** Correctly signed, or with a readable header, but a length, string or address is invalid. */
    MALFORMED,
    /**
     * A sequence number not above the highest one already seen from that container, on a packet
     * sent more than {@link ReplayGuard#OVERTAKEN_MILLIS} before that one.
     */
    REPLAYED,
    /**
     * A sequence number not above the highest one already seen from that container, on a packet
     * sent at most {@link ReplayGuard#OVERTAKEN_MILLIS} before that one: delivered twice, or
     * overtaken by a later one (a sender's answers and its announcements reach a container on
     * different sockets). Its news is no newer than what was accepted. Counted, logged at DEBUG.
     */
    OVERTAKEN,
    /** A timestamp too far from our clock: an old packet replayed, or unsynchronised clocks. */
    CLOCK_SKEW,
    /** One of this container's own announcements, looped back to it. */
    OWN,
    /**
     * Not read at all: {@link Receiver#MAX_WAITING} datagrams were already waiting for this
     * container to handle them (its JVM is too busy to keep up).
     */
    BACKLOG
  }

  private final Reason reason;

  BadPacketException(Reason reason, String message) {
    super(message);
    this.reason = Objects.requireNonNull(reason, "reason == null");
  }

  /** Why the packet was dropped; never null. */
  public Reason reason() {
    return reason;
  }

  // A dropped packet is routine, not a bug: the stack trace would only cost time under a flood.
  @Override
  public synchronized Throwable fillInStackTrace() {
    return this;
  }
}
