package dev.trade.internal.net;

import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Heartbeat;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.LinkHandler;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.Replication;
import dev.trade.internal.net.remote.RemoteCalls;
import java.io.IOException;

/**
 * What a container does with each frame its links read, on the reading thread: calls and replies
 * take the fast path ({@link RemoteCalls}), replication frames go to the control thread in order
 * (copies that are already stale are dropped here, before they queue), heartbeats count as life
 * and time the link ({@link Heartbeat#pinged}). Safe for concurrent use.
 */
final class FrameDispatcher implements LinkHandler {
  /** Why a link closed when its peer said GOODBYE: an orderly close. */
  static final String GOODBYE = "said goodbye";

  private final RemoteCalls calls;
  private final Replication replication;
  private final Network network;
  private final Heartbeat heartbeat;
  private final long backlogLimit;

  /**
   * @param backlogLimit how many bytes of one link's replication frames may wait for the control
   *     thread (see {@link ControlBacklog}); a link that sends more is closed
   */
  FrameDispatcher(RemoteCalls calls, Replication replication, Network network,
      Heartbeat heartbeat, long backlogLimit) {
    this.calls = calls;
    this.replication = replication;
    this.network = network;
    this.heartbeat = heartbeat;
    this.backlogLimit = backlogLimit;
  }

  /**
   * The backlog limit for links of a container with this MAXFRAMESIZE: two of the largest frames,
   * and at least 16 MiB, which a system of a hundred containers starting at once stays far below.
   */
  static long backlogLimit(int maxFrameSize) {
    return Math.max(2L * maxFrameSize, 16L << 20);
  }

  @Override
  public boolean frame(Link link, int type, byte[] payload) throws IOException {
    switch (type) {
      case Wire.CALL:
      case Wire.REPLY:
        if (payload.length < (type == Wire.CALL ? Frames.MIN_CALL : Frames.MIN_REPLY)) {
          throw new IOException((type == Wire.CALL ? "CALL" : "REPLY") + " of " + payload.length
              + " bytes, shorter than its fixed fields (" + (type == Wire.CALL ? Frames.MIN_CALL
              : Frames.MIN_REPLY) + ")");
        }
        return type == Wire.CALL ? calls.onCall(link, payload) : calls.onReply(link, payload);
      case Wire.PING:
        heartbeat.pinged(link, payload);
        break;
      case Wire.GOODBYE:
        link.close(GOODBYE);
        break;
      case Wire.LINKS:
      case Wire.TABLE:
      case Wire.DELTA:
        // Not stale: the link asked isStale first.
      case Wire.TABLE_REQUEST:
      case Wire.DIGEST: {
        long held = link.backlog.hold(payload.length, backlogLimit);
        if (held < 0) {
          throw new IOException("flooding: more than " + backlogLimit + " bytes of its replication"
              + " frames wait to be applied here");
        }
        network.onControl(() -> {
          link.backlog.release(held);
          replication.received(link, type, payload);
        });
        break;
      }
      default:
        throw new IOException("unknown frame type " + type);
    }
    return true;
  }

  @Override
  public boolean isStale(Link link, int type, byte[] buf, int off, int len) {
    return (type == Wire.LINKS || type == Wire.TABLE || type == Wire.DELTA)
        && replication.isStale(link, type, buf, off, len);
  }

  @Override
  public boolean abandoned(byte[] frame) {
    return calls.abandoned(frame);
  }

  @Override
  public void closed(Link link, String reason) {
    network.linkClosed(link, reason);
  }
}
