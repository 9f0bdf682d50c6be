package dev.trade.internal.net.remote;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADELockedException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.TRADETimeoutException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.Provider;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.ReplyWait;
import dev.trade.internal.net.link.ServedCalls;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.time.Scheduler;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.util.Arrays;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Predicate;

/**
 * Remote calls over links, by frame: the calling side (request ids, pending replies, deadlines),
 * forwarding of calls and replies between containers that have no direct link, and the way back:
 * building REPLY frames and taking them to their callers, also when a route is missing or has
 * just broken. The providing side is {@link CallServer}, which answers through this way back.
 *
 * <p>A link's reading thread serves the calls it reads and completes the futures of replies; a
 * {@link ReadWatch} keeps the link read while a call takes long, so one slow service never stalls
 * a connection. This class is safe for concurrent use.
 */
public final class RemoteCalls {
  private static final Logger LOG = System.getLogger("dev.trade.net");
  /** The longest text of a failure reply that callers read, in bytes of UTF-8. */
  static final int MAX_TEXT = 64 * 1024;
  /**
   * The most calls of one link served at once by threads other than the one reading it (each a
   * thread); a call read beyond them is answered "not available now" at once. A neighbour that
   * sends calls faster than they end, to a slow service, would otherwise start threads without
   * bound; this way the link goes on being read (a link not read is soon closed as silent).
   */
  public static final int MAX_SERVED_PER_LINK = 512;
  private static final int MAX_IDS = 4096;
  /**
   * How many times a CALL whose next hop is the neighbour it came from waits for routes to settle
   * (10, 20, 40, 80 and 160 ms: 310 ms in all) before it is passed back all the same.
   */
  static final int ROUTE_WAITS = 5;
  /**
   * The most calls passed on whose replies are awaited at once; beyond it those no longer awaited
   * are forgotten, and if none is, a call is answered "not available now" instead of passed on.
   */
  private static final int MAX_PASSED_ON = 16_384;

  /** Finds the link a frame for a container leaves by. */
  public interface Router {
    /** The link towards {@code container}, or null when it is not reachable. */
    Link nextHop(UUID container);
  }

  /** A call sent and not answered yet, until {@code deadline} (nanoTime). */
  /** A call passed on: its caller and request id. */
  private record Passed(UUID caller, long requestId) {}

  /** Where a call passed on came from and went, and until when (nanoTime) its reply is awaited. */
  private record PassedOn(Link in, Link out, long until) {}

  /** How long after its timeout a passed-on call's reply is still passed back. */
  private static final long REPLY_GRACE_NANOS = TimeUnit.SECONDS.toNanos(2);

  record Pending(CompletableFuture<byte[]> reply, UUID destination, UUID via, long deadline,
      ServiceDescriptor service, long timeoutNanos) {
    /** What the caller gets when the deadline passed. */
    TRADETimeoutException timedOut() {
      return CallErrors.timedOut(service, timeoutNanos, "");
    }
  }

  private final UUID self;
  private final Codec codec;
  private final Router router;
  private final CallServer serving;
  private final int maxFrame;
  private final AtomicLong nextId = new AtomicLong();
  private final Map<Long, Pending> pending = new ConcurrentHashMap<>();
  /**
   * The calls this container passed on, by caller and request id, until their replies come back
   * or their time is up: a REPLY is passed on only as the answer to one of them (see onReply).
   */
  private final Map<Passed, PassedOn> passedOn = new ConcurrentHashMap<>();
  /** REPLY frames dropped because no call of theirs went out that way (see onReply). */
  private final AtomicLong strayReplies = new AtomicLong();
  /** Parsed container ids of the services called (parsing one costs more than a lookup). */
  private final Map<String, UUID> containerIds = new ConcurrentHashMap<>();
  private final ReplyWait replyWait = new ReplyWait();
  private final Deadlines deadlines;
  private final Scheduler scheduler;

  /**
   * @param scheduler the container's clock and timer (deadlines, waits for routes to settle)
   * @param maxFrame the largest frame (after its length field) that peers accept: MAXFRAMESIZE
   */
  public RemoteCalls(UUID self, Codec codec, Router router, Provider host, Scheduler scheduler,
      int maxFrame) {
    this.self = self;
    this.codec = codec;
    this.router = router;
    this.serving = new CallServer(self, codec, host, this, maxFrame);
    this.maxFrame = maxFrame;
    this.deadlines = new Deadlines(scheduler, pending);
    this.scheduler = scheduler;
  }

  /** Calls a service of another container and waits for its reply until the deadline. */
  public Object call(ServiceDescriptor d, Object[] args, CallContext context, long deadlineNanos,
      ClassLoader loader, Set<String> declared) throws TRADEException {
    UUID destination = destination(d);
    Link link = nextHop(d, destination);
    long id = nextId.incrementAndGet();
    long sent = System.nanoTime();
    long remaining = deadlineNanos - sent;
    byte[] frame = fittingFrame(d, link, destination, id, remaining, args, context);
    if (!link.output.hasRoom()) {
      awaitRoom(link, d, deadlineNanos, remaining);
    }
    Pending p = new Pending(new CompletableFuture<>(), destination, link.peerId, deadlineNanos, d,
        remaining);
    pending.put(id, p);
    deadlines.watch();
    // A service calling out while it is served on a link's reading thread: the reply may come over
    // that link, so it must go on being read.
    ServedCalls.releaseReading();
    // Before sending: the link's thread must know a caller may read the reply before it comes.
    boolean borrowed = replyWait.borrow(link);
    boolean sentOk = false;
    try {
      link.send(frame);
      if (link.isClosed()) { // closed between lookup and registration: nobody will fail us
        throw new IOException("link closed");
      }
      sentOk = true;
    } catch (IOException e) {
      pending.remove(id);
      throw CallErrors.gone(d, "the connection to its container was lost");
    } finally {
      if (!sentOk) {
        replyWait.abandon(link, borrowed);
      }
    }
    byte[] reply;
    try {
      reply = replyWait.await(link, borrowed, p.reply, sent);
    } catch (ExecutionException e) {
      throw (TRADEException) e.getCause();
    } catch (InterruptedException e) {
      pending.remove(id);
      Thread.currentThread().interrupt();
      throw new TRADEException("Interrupted while waiting for " + d.signature());
    }
    return decodeReply(d, reply, loader, declared);
  }

  /**
   * Calls a service of another container without waiting: the future completes with the decoded
   * reply (decoded on {@code executor}, never on the link's thread), or fails when the deadline
   * passes ({@link Deadlines}) or the link or container is lost. No thread waits meanwhile: the
   * link's reading thread completes the reply, and reading is not lent to callers while the call is
   * outstanding ({@link Link#awaitedWithoutReading}), since nobody else would read its reply. A call that
   * finds the link congested fails at once instead of waiting for room.
   */
  public CompletableFuture<Object> callAsync(ServiceDescriptor d, Object[] args,
      CallContext context, long deadlineNanos, ClassLoader loader, Set<String> declared,
      Executor executor) {
    try {
      UUID destination = destination(d);
      Link link = nextHop(d, destination);
      long id = nextId.incrementAndGet();
      long remaining = deadlineNanos - System.nanoTime();
      byte[] frame = fittingFrame(d, link, destination, id, remaining, args, context);
      if (!link.output.hasRoom()) {
        throw new TRADEServiceUnavailableException(CallErrors.notNowText("the link to "
            + link.peerName + " holds " + link.output.queuedBytes() + " bytes that it takes slower"
            + " than they are sent, and an asynchronous call does not wait for room"));
      }
      Pending p = new Pending(new CompletableFuture<>(), destination, link.peerId, deadlineNanos, d,
          remaining);
      link.awaitedWithoutReading(p.reply);
      pending.put(id, p);
      deadlines.watch();
      try {
        link.send(frame);
        if (link.isClosed()) {
          throw new IOException("link closed");
        }
      } catch (IOException e) {
        if (pending.remove(id) != null) {
          p.reply.completeExceptionally(
              CallErrors.gone(d, "the connection to its container was lost"));
        }
      }
      return p.reply.thenApplyAsync(payload -> {
        try {
          return decodeReply(d, payload, loader, declared);
        } catch (TRADEException e) {
          throw new CompletionException(e);
        }
      }, executor);
    } catch (TRADEException e) {
      return CompletableFuture.failedFuture(e);
    }
  }

  /** The id of {@code d}'s container. */
  private UUID destination(ServiceDescriptor d) {
    UUID destination = containerIds.get(d.containerId());
    if (destination == null) {
      if (containerIds.size() >= MAX_IDS) {
        containerIds.clear(); // ids of containers long gone; the live ones come back at once
      }
      destination = UUID.fromString(d.containerId());
      containerIds.put(d.containerId(), destination);
    }
    return destination;
  }

  private Link nextHop(ServiceDescriptor d, UUID destination) throws TRADEException {
    Link link = router.nextHop(destination);
    if (link == null) {
      throw CallErrors.gone(d, "its container is not reachable");
    }
    return link;
  }

  /** The CALL frame, checked against what {@code link}'s peer accepts. */
  private byte[] fittingFrame(ServiceDescriptor d, Link link, UUID destination, long id,
      long remaining, Object[] args, CallContext context) throws TRADESerializationException {
    byte[] frame = callFrame(destination, id, d.serviceId(),
        (int) Math.min(Integer.MAX_VALUE, Math.max(1, TimeUnit.NANOSECONDS.toMillis(remaining))), args,
        context);
    if (!Frames.fits(frame, link.sendLimit)) {
      // Each value fits its limit, but not the call as a whole; the peer would drop the link.
      throw new TRADESerializationException("Cannot call " + d.signature() + ": its arguments need "
          + (frame.length - 4) + " bytes, more than " + limitOf(link, maxFrame));
    }
    return frame;
  }

  /**
   * Waits while the link holds {@link LinkOutput#ROOM} bytes or more not yet written: its peer
   * takes them slower than calls are made, and the caller waits for it rather than the queue
   * growing without bound; until the call's deadline.
   */
  private static void awaitRoom(Link link, ServiceDescriptor d, long deadline, long timeout)
      throws TRADEException {
    try {
      if (!link.output.awaitRoom(deadline, link::isClosed)) {
        throw CallErrors.timedOut(d, timeout, ": the call waited all that time to be sent, behind "
            + link.output.queuedBytes() + " bytes that " + link.peerName
            + " takes slower than they are sent");
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new TRADEException("Interrupted while waiting to send a call to " + d.signature());
    }
  }

  /** A CALL frame (header included) for a service of {@code destination}. */
  public byte[] callFrame(UUID destination, long requestId, long serviceId, int timeoutMs, Object[] args)
      throws TRADESerializationException {
    return callFrame(destination, requestId, serviceId, timeoutMs, args, CallContext.EMPTY);
  }

  /** A CALL frame (header included) for a service of {@code destination}, with a context. */
  public byte[] callFrame(UUID destination, long requestId, long serviceId, int timeoutMs, Object[] args,
      CallContext context) throws TRADESerializationException {
    ByteSink out = Frames.start(Wire.CALL, 64);
    Frames.writeRouting(out, self, destination, Wire.MAX_HOPS);
    out.writeLong(requestId);
    out.writeLong(serviceId);
    out.writeInt(timeoutMs);
    out.writeVarUInt(args.length);
    for (Object a : args) {
      codec.write(a, out);
    }
    ContextCoding.write(context, out);
    return Frames.finish(out);
  }

  private Object decodeReply(ServiceDescriptor d, byte[] payload, ClassLoader loader,
      Set<String> declared) throws TRADEException {
    ByteSource in = ByteSource.of(payload, Frames.ROUTING + 8, payload.length - Frames.ROUTING - 8);
    int status = in.readUnsignedByte();
    switch (status) {
      case Wire.OK:
        return codec.read(in, loader, declared);
      case Wire.FAILED_INVOCATION:
        Object t = codec.read(in, loader, declared);
        Throwable cause = t instanceof Throwable ? (Throwable) t : null;
        throw new TRADEInvocationException("Service " + d.signature() + " threw "
            + (cause == null ? "an exception" : cause.toString()), cause);
      case Wire.FAILED_UNAVAILABLE:
        throw new TRADEServiceUnavailableException(in.readText(MAX_TEXT));
      case Wire.FAILED_BAD_ARGUMENTS:
        throw new TRADEBadArgumentsException(in.readText(MAX_TEXT));
      case Wire.FAILED_SERIALIZATION:
        throw new TRADESerializationException(in.readText(MAX_TEXT));
      case Wire.FAILED_TIMEOUT:
        throw new TRADETimeoutException(in.readText(MAX_TEXT));
      case Wire.FAILED_LOCKED:
        throw new TRADELockedException(in.readText(MAX_TEXT));
      case Wire.FAILED_NOT_AUTHORIZED:
        throw new TRADENotAuthorizedException(in.readText(MAX_TEXT));
      default:
        throw new TRADEException(in.readText(MAX_TEXT));
    }
  }

  /**
   * A CALL frame arrived over {@code from} (its reading thread), which serves it itself: the call
   * runs without waiting for another thread to wake up, and the link goes on being read elsewhere
   * if it takes long (see {@link ReadWatch}).
   *
   * @return true if this thread still reads {@code from}
   */
  public boolean onCall(Link from, byte[] payload) {
    int timeoutMs = Frames.callTimeout(payload);
    if (timeoutMs <= 0) {
      // Senders write at least 1 ms: none left means the caller has given up, or a broken peer.
      reply(from, payload, Wire.FAILED_TIMEOUT, "The call arrived at container " + self
          + " with no time left (timeout " + timeoutMs + " ms); it was neither run nor passed on");
      return true;
    }
    UUID destination = Frames.destination(payload);
    if (!destination.equals(self)) {
      // Passing a frame on writes to another link, which can block (its peer slow or not
      // reading): like a call served here, the link it came over is read elsewhere meanwhile.
      return from.serveHere(() -> forward(from, payload, destination, 0));
    }
    if (from.servedElsewhere() >= MAX_SERVED_PER_LINK) {
      reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.notNowText("container "
          + self + " serves " + MAX_SERVED_PER_LINK + " calls from this link at once already"));
      return true;
    }
    return from.serveHere(() -> serving.serve(from, payload));
  }

  /**
   * Whether {@code frame} (header included) is a CALL made here whose caller has given up on it
   * (its deadline passed, or it failed): a congested link need not carry it any more, and its
   * service should not run long after its caller went on without it.
   */
  public boolean abandoned(byte[] frame) {
    int at = Wire.HEADER;
    return Frames.isCall(frame)
        && Frames.getLong(frame, at) == self.getMostSignificantBits()
        && Frames.getLong(frame, at + 8) == self.getLeastSignificantBits()
        && !pending.containsKey(Frames.getLong(frame, at + Frames.ROUTING));
  }

  /**
   * A REPLY frame arrived over {@code from} (its reading thread).
   *
   * @return true if this thread still reads {@code from}
   */
  /**
   * A REPLY is accepted only over the link its call went out on: a reply retraces its call's path
   * (the provider answers over the link the call came in on, and each container that passed the
   * call on passes the reply back over the link the call came from), so whatever arrives that way
   * comes from the provider or from a container on the path that could not pass the call on. A
   * member that is not on the call's path cannot answer for the provider, whatever request id it
   * guesses, and a container never passes on a reply that names it as its source. Anything else is
   * dropped and counted, not an error: the call's path may have broken meanwhile.
   */
  public boolean onReply(Link from, byte[] payload) {
    UUID destination = Frames.destination(payload);
    long id = Frames.requestId(payload);
    UUID source = Frames.source(payload);
    if (!destination.equals(self)) {
      PassedOn route = passedOn.get(new Passed(destination, id));
      if (route == null || route.out != from || source.equals(self)
          || !passedOn.remove(new Passed(destination, id), route)) {
        stray(from, payload);
        return true;
      }
      return from.serveHere(() -> passBack(route, payload, destination));
    }
    Pending p = pending.get(id);
    if (p == null || !p.via.equals(from.peerId) || !pending.remove(id, p)) {
      stray(from, payload);
      return true;
    }
    p.reply.complete(payload);
    return true;
  }

  private void stray(Link from, byte[] payload) {
    strayReplies.incrementAndGet();
    LOG.log(Level.DEBUG, "dropped a reply from {0} for {1} (request {2}) over the link to {3}: no "
        + "call of that id went that way", Frames.source(payload), Frames.destination(payload),
        Frames.requestId(payload), from.peerName);
  }

  /** REPLY frames dropped because no call of theirs went out that way (for tests). */
  long strayReplies() {
    return strayReplies.get();
  }

  /** Passes a reply back over the link its call came from (while that link is open). */
  private void passBack(PassedOn route, byte[] payload, UUID caller) {
    if (Frames.hops(payload) <= 1) {
      return;
    }
    if (!sent(route.in, Frames.forwarded(Wire.REPLY, payload))) {
      LOG.log(Level.DEBUG, "reply to {0} dropped: the link its call came from closed", caller);
    }
  }

  /** Forgets the calls passed on whose replies are no longer awaited at {@code now} (nanoTime). */
  private void forgetPassed(long now) {
    passedOn.values().removeIf(r -> now - r.until > 0);
  }

  /**
   * @param from the link a CALL came in on (for its failure reply); null for a REPLY
   * @param waits how many times the CALL waited for routes to settle already
   */
  private void forward(Link from, byte[] payload, UUID destination, int waits) {
    Link next = router.nextHop(destination);
    if (next == from && waits < ROUTE_WAITS && Frames.spendCallTime(payload, 10 << waits)) {
      // The neighbour that passed the call here has this container on its shortest path to the
      // destination, and this container has it on its own: their link states disagree for the
      // moment (a link just came or went). Passed back, the call would go round until its hops ran
      // out; it waits for routes to settle instead, as a reply does ({@link #deliver}), and the
      // wait counts against its timeout.
      try {
        scheduler.timer().schedule(() -> forward(from, payload, destination, waits + 1),
            10 << waits, TimeUnit.MILLISECONDS);
        return;
      } catch (RejectedExecutionException closing) {
        // Passed back below, or failed.
      }
    }
    if (next == null || Frames.hops(payload) <= 1) {
      LOG.log(Level.DEBUG, "dropping frame for unreachable {0}", destination);
      reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.goneText("container "
          + destination + " is not reachable from " + self));
      return;
    }
    byte[] frame = Frames.forwarded(Wire.CALL, payload);
    if (!next.output.hasRoom()) {
      // A reading thread must not wait for room: it would stop reading the link the call came on.
      reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.notNowText("the link from "
          + self + " to " + next.peerName + " holds " + next.output.queuedBytes()
          + " bytes that it takes slower than they are sent"));
      return;
    }
    if (!Frames.fits(frame, next.sendLimit)) {
      reply(from, payload, Wire.FAILED_SERIALIZATION, "Cannot pass the call on from "
          + self + ": it needs " + (frame.length - 4) + " bytes, more than "
          + limitOf(next, maxFrame));
      return;
    }
    long now = System.nanoTime();
    Passed key = new Passed(Frames.source(payload), Frames.requestId(payload));
    PassedOn route = new PassedOn(from, next,
        now + TimeUnit.MILLISECONDS.toNanos(Math.max(0, Frames.callTimeout(payload)))
            + REPLY_GRACE_NANOS);
    if (passedOn.size() >= MAX_PASSED_ON) {
      forgetPassed(now);
      if (passedOn.size() >= MAX_PASSED_ON) {
        // Each holds two links until its reply or its time is up: a member that sends calls to
        // pass on with long timeouts and lets no reply come must not make this grow without end.
        reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.notNowText("container " + self
            + " passes on " + MAX_PASSED_ON + " calls whose replies have not come back yet"));
        return;
      }
    }
    passedOn.put(key, route);
    try {
      next.passOn(frame);
    } catch (IOException e) {
      passedOn.remove(key, route);
      reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.goneText("the route to container "
          + destination + " was lost"));
    }
  }

  /** Fails at once every call waiting on {@code container} (it left or became unreachable). */
  public void failTo(UUID container, String why) {
    fail(p -> p.destination.equals(container), why);
  }

  /**
   * Fails at once every call that left through the link to {@code neighbour}, and forgets the
   * calls passed on that came or went over it: their replies cannot come back that way.
   */
  public void failVia(UUID neighbour, String why) {
    fail(p -> p.via.equals(neighbour), why);
    passedOn.values().removeIf(
        r -> r.in.peerId.equals(neighbour) || r.out.peerId.equals(neighbour));
  }

  /** Fails every waiting call (the container closes). */
  public void failAll(String why) {
    fail(p -> true, why);
  }

  private void fail(Predicate<Pending> which, String why) {
    pending.values().removeIf(p -> which.test(p) && p.reply.completeExceptionally(
        new TRADEServiceUnavailableException(CallErrors.goneText(why))));
  }

  // The way back.

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
    int maxChars = Math.min(MAX_TEXT, limit - 64) / 3;
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
