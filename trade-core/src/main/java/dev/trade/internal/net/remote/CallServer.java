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
import dev.trade.internal.call.Caller;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.Provider;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.MalformedValueException;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.util.UUID;
import java.util.concurrent.TimeUnit;

/**
 * The providing side of remote calls: decodes a CALL's arguments, runs the host's call chain with
 * the caller's deadline, and replies with the outcome, one REPLY for every CALL whatever happens
 * (docs/protocol.md, "CALL" and "REPLY"). Runs on whichever thread serves the call; stateless
 * beyond what it is made with, so safe for concurrent use.
 */
final class CallServer {
  private static final Logger LOG = System.getLogger("dev.trade.net");

  private final UUID self;
  private final Codec codec;
  private final Provider host;
  private final RemoteCalls replies;
  private final int maxFrame;

  /** @param maxFrame this container's MAXFRAMESIZE */
  CallServer(UUID self, Codec codec, Provider host, RemoteCalls replies, int maxFrame) {
    this.self = self;
    this.codec = codec;
    this.host = host;
    this.replies = replies;
    this.maxFrame = maxFrame;
  }

  /** Serves a CALL addressed to this container that came over {@code from}; always replies. */
  void serve(Link from, byte[] payload) {
    ByteSource in = ByteSource.of(payload, Frames.ROUTING, payload.length - Frames.ROUTING);
    try {
      in.readLong(); // request id, echoed by RemoteCalls.replyStart
      long serviceId = in.readLong();
      int timeoutMs = in.readInt();
      int count = in.readVarUInt();
      LocalService s = host.local(serviceId);
      if (s == null) {
        replies.reply(from, payload, Wire.FAILED_UNAVAILABLE, CallErrors.goneText("service "
            + serviceId + " was deregistered from container " + self));
        return;
      }
      ServiceDescriptor d = s.descriptor();
      if (count != d.parameterTypeNames().size()) {
        replies.reply(from, payload, Wire.FAILED_BAD_ARGUMENTS,
            CallErrors.argumentCount(d, count).getMessage());
        return;
      }
      ClassLoader loader = s.target().getClass().getClassLoader();
      Object[] args = new Object[count];
      for (int i = 0; i < count; i++) {
        args[i] = codec.read(in, loader == null ? ClassLoader.getSystemClassLoader() : loader,
            s.declaredTypes());
      }
      CallContext context = ContextCoding.read(in);
      long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
      Object result = host.invoke(new Invocation(d, args, deadline,
          Caller.of(Frames.source(payload)), context));
      ByteSink out = replies.replyStart(payload, Wire.OK);
      try {
        codec.write(result, out);
      } catch (TRADESerializationException e) {
        replies.reply(from, payload, Wire.FAILED_SERIALIZATION, "The result of " + d.signature()
            + " cannot travel: " + e.getMessage());
        return;
      }
      byte[] frame = Frames.finish(out);
      if (!fits(frame)) {
        replies.reply(from, payload, Wire.FAILED_SERIALIZATION, "The result of " + d.signature()
            + " cannot travel: the reply needs " + (frame.length - 4)
            + " bytes, more than MAXFRAMESIZE=" + maxFrame);
        return;
      }
      replies.sendReply(from, payload, frame);
    } catch (TRADEInvocationException e) {
      ByteSink out = replies.replyStart(payload, Wire.FAILED_INVOCATION);
      try {
        codec.write(e.getCause(), out);
        byte[] frame = Frames.finish(out);
        if (fits(frame)) {
          replies.sendReply(from, payload, frame);
        } else {
          replies.reply(from, payload, Wire.FAILED_OTHER, e.getMessage());
        }
      } catch (TRADESerializationException notEncodable) {
        replies.reply(from, payload, Wire.FAILED_OTHER, e.getMessage());
      }
    } catch (TRADEServiceUnavailableException e) {
      replies.reply(from, payload, Wire.FAILED_UNAVAILABLE, e.getMessage());
    } catch (TRADEBadArgumentsException e) {
      replies.reply(from, payload, Wire.FAILED_BAD_ARGUMENTS, e.getMessage());
    } catch (MalformedValueException e) {
      replies.reply(from, payload, Wire.FAILED_SERIALIZATION, "malformed call: " + e.getMessage());
      if (Frames.source(payload).equals(from.peerId)) {
        // The peer itself wrote bytes that are not a value: it is broken or hostile.
        LOG.log(Level.WARNING, "malformed call from {0}: {1}; closing the connection",
            from.peerName, e.getMessage());
        from.closeAfterSending("malformed call: " + e.getMessage());
      }
    } catch (TRADESerializationException e) {
      replies.reply(from, payload, Wire.FAILED_SERIALIZATION, e.getMessage());
    } catch (TRADETimeoutException e) {
      replies.reply(from, payload, Wire.FAILED_TIMEOUT, e.getMessage());
    } catch (TRADELockedException e) {
      replies.reply(from, payload, Wire.FAILED_LOCKED, e.getMessage());
    } catch (TRADENotAuthorizedException e) {
      replies.reply(from, payload, Wire.FAILED_NOT_AUTHORIZED, e.getMessage());
    } catch (TRADEException | RuntimeException e) {
      replies.reply(from, payload, Wire.FAILED_OTHER, String.valueOf(e.getMessage()));
    }
  }

  /** Whether a finished frame is within this container's own MAXFRAMESIZE. */
  private boolean fits(byte[] frame) {
    return Frames.fits(frame, maxFrame);
  }
}
