package dev.trade.internal.net.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.LoopbackLinks;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.time.Scheduler;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.UUID;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Which link a reply leaves by: the one its call came in on, even when the route table points
 * elsewhere (it may lead over a link that is going down, or not know the way yet); the route only
 * when that link has closed.
 */
class ReplyWayBackTest {
  private final UUID self = UUID.randomUUID();
  private final UUID caller = UUID.randomUUID();
  private final Scheduler timer = Scheduler.system("test");
  private final LoopbackLinks loopback = new LoopbackLinks();

  @AfterEach
  void close() throws IOException {
    loopback.close();
    timer.close();
  }

  /** A CALL payload from the caller to this container: the routing header and a request id. */
  private byte[] call() {
    ByteSink out = new ByteSink(64);
    Frames.writeRouting(out, caller, self, Wire.MAX_HOPS);
    out.writeLong(7);
    return out.toByteArray();
  }

  @Test
  void aReplyGoesBackTheWayItsCallCameNotAlongTheRoute() throws Exception {
    InputStream[] atCameBy = new InputStream[1];
    InputStream[] atRoute = new InputStream[1];
    Link cameBy = loopback.link(UUID.randomUUID(), "came-by", atCameBy);
    Link route = loopback.link(UUID.randomUUID(), "route", atRoute);
    RemoteCalls replies = new RemoteCalls(self, null,
        container -> container.equals(caller) ? route : null, null, timer, 1 << 20);
    byte[] call = call();
    byte[] frame = Frames.finish(replies.replyStart(call, Wire.OK));

    replies.sendReply(cameBy, call, frame);
    // On loopback, what is written is at the far end when the write returns.
    DataInputStream in = new DataInputStream(atCameBy[0]);
    assertEquals(frame.length - 4, in.readInt());
    in.skipNBytes(frame.length - 4);
    assertEquals(0, atRoute[0].available(), "not along the route");

    cameBy.close("gone");
    replies.sendReply(cameBy, call, frame);
    assertEquals(frame.length - 4, new DataInputStream(atRoute[0]).readInt(),
        "the link it came by has closed: along the route");
  }
}
