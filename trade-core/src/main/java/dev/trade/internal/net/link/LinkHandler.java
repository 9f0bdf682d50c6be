package dev.trade.internal.net.link;

import java.io.IOException;

/** Receives what a {@link Link} reads; called on the thread that is reading the link. */
public interface LinkHandler {
  /** @return true to go on reading on this thread, false if reading went on in another one */
  boolean frame(Link link, int type, byte[] payload) throws IOException;

  /**
   * Whether a frame is a copy of something this container has: then it is dropped, not handed
   * to {@link #frame}. Asked once per frame, before {@code frame}; the payload is {@code len}
   * bytes of {@code buf} from {@code off}, often the link's input buffer, valid only during
   * the call.
   */
  default boolean isStale(Link link, int type, byte[] buf, int off, int len) {
    return false;
  }

  /**
   * Whether a frame queued for writing need not go out any more: a call whose caller has given
   * up on it. Asked by the link's writer, only while much waits to be written.
   */
  default boolean abandoned(byte[] frame) {
    return false;
  }

  /** The link ended (closed, or its reading failed): called once, with why. */
  void closed(Link link, String reason);
}
