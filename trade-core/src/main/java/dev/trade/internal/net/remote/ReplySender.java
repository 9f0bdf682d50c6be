package dev.trade.internal.net.remote;

import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.time.Scheduler;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.util.Arrays;
import java.util.UUID;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;

/**
 * The way back of remote calls: builds the REPLY frames of calls served here and sends them, and
 * the replies forwarded on behalf of other containers, towards their callers, also when a route
 * is missing or has just broken.
 *
 * <p>Safe for concurrent use: it holds no state of its own beyond what it is made with; a reply
 * that finds no route is tried again on the timer.
 */
public final class ReplySender {
  private static final Logger LOG = System.getLogger("dev.trade.net");

  private final UUID self;
  private final RemoteCalls.Router router;
  private final Scheduler scheduler;
  private final int maxFrame;

  /** @param maxFrame the largest frame (after its length field) that peers accept: MAXFRAMESIZE */
  public ReplySender(UUID self, RemoteCalls.Router router, Scheduler scheduler, int maxFrame) {
    this.self = self;
    this.router = router;
    this.scheduler = scheduler;
    this.maxFrame = maxFrame;
  }

  /** A reply frame's start: routing back to the caller, the request id and a status. */
  public ByteSink replyStart(byte[] call, int status) {
    ByteSink out = Frames.start(Wire.REPLY, 64);
    Frames.writeRouting(out, self, Frames.source(call), Wire.MAX_HOPS);
    out.writeBytes(call, Frames.ROUTING, 8);
    out.writeByte(status);
    return out;
  }

  /** A reply carrying only a text, shortened to what callers read (MAX_TEXT bytes of UTF-8). */
  void reply(Link from, byte[] call, int status, String text) {
    ByteSink out = replyStart(call, status);
    out.writeText(clip(text == null ? "" : text, from == null ? maxFrame : from.sendLimit));
    sendReply(from, call, Frames.finish(out));
  }

  /**
   * Cuts a reply text to what the caller reads ({@code MAX_TEXT} bytes) and a frame of at most
   * {@code limit} bytes holds: a char takes at most 3 bytes of UTF-8.
   */
  private static String clip(String text, int limit) {
    int maxChars = Math.min(RemoteCalls.MAX_TEXT, limit - 64) / 3;
    return text.length() <= maxChars ? text : text.substring(0, maxChars);
  }

  /**
   * What limits frames over {@code link}, for error texts: this container's MAXFRAMESIZE, or the
   * smaller limit the peer declared.
   */
  static String limitOf(Link link, int ownLimit) {
    return link.sendLimit < ownLimit
        ? link.sendLimit + ", which container '" + link.peerName + "' accepts (its MAXFRAMESIZE)"
        : "MAXFRAMESIZE=" + ownLimit;
  }

  /**
   * Stands in for a reply too large for {@code link}, whose peer would close the link over it: a
   * reply to the same call that says so, status 4 in place of a result and 6 in place of anything
   * else, sent as a container that gives up forwarding sends its own.
   */
  private byte[] tooLarge(byte[] frame, Link link) {
    byte[] head = Arrays.copyOfRange(frame, Wire.HEADER, Wire.HEADER + Frames.ROUTING + 9);
    boolean result = head[Frames.ROUTING + 8] == Wire.OK;
    ByteSink out = Frames.start(Wire.REPLY, 192);
    Frames.writeRouting(out, self, Frames.destination(head), Wire.MAX_HOPS);
    out.writeBytes(head, Frames.ROUTING, 8);
    out.writeByte(result ? Wire.FAILED_SERIALIZATION : Wire.FAILED_OTHER);
    out.writeText(clip("The " + (result ? "result" : "reply") + " cannot travel: it needs "
        + (frame.length - 4) + " bytes, more than " + limitOf(link, maxFrame), link.sendLimit));
    return Frames.finish(out);
  }

  /**
   * Sends a reply to its caller: straight back over the link the call came in on, else (that link
   * closed) along the route. The neighbour that passed the call on is the caller or knows the way
   * back, having just forwarded it, and that way is as short as the caller's route here. The route
   * from here may not know it yet (a call can overtake link states: a new neighbour's first calls,
   * calls along a path that just formed), or may still lead over a link that is going down, whose
   * failing write can come after this returns (another thread writing, or the reader's burst) and
   * would lose the reply, leaving the caller waiting for its deadline.
   */
  void sendReply(Link from, byte[] call, byte[] frame) {
    if (sent(from, frame)) {
      return;
    }
    UUID caller = Frames.source(call);
    Link route = router.nextHop(caller);
    if (route == from || !sent(route, frame)) {
      deliver(caller, frame, 0); // both failed just now: wait for routes to settle
    }
  }

  /**
   * Sends over {@code link} if it is there and open; false if not or if the write failed. A frame
   * too large for the link is replaced by one that says so (see {@link #tooLarge}).
   */
  private boolean sent(Link link, byte[] frame) {
    if (link == null || link.isClosed()) {
      return false;
    }
    try {
      link.send(Frames.fits(frame, link.sendLimit) ? frame : tooLarge(frame, link));
      return true;
    } catch (IOException e) {
      return false;
    }
  }

  /**
   * Sends a reply towards its caller. When the route is broken (a link just failed and routes are
   * being recomputed), tries again a few times over about half a second: a caller must not wait for
   * its deadline because a reply met a stale route.
   */
  void deliver(UUID caller, byte[] frame, int attempt) {
    if (sent(router.nextHop(caller), frame)) {
      return;
    }
    if (attempt >= 6) {
      LOG.log(Level.DEBUG, "reply to {0} dropped: no route", caller);
      return;
    }
    try {
      scheduler.timer().schedule(() -> deliver(caller, frame, attempt + 1), 10L << attempt,
          TimeUnit.MILLISECONDS);
    } catch (RejectedExecutionException closing) {
      // The container is closing; its callers fail on their own.
    }
  }
}
