package dev.trade.internal.net;

import java.io.BufferedInputStream;
import java.io.InputStream;

/**
 * A link's input buffer, which also tells whether the next frame has arrived whole: then the
 * reading thread can go on without blocking, so it may hold back replies until it must wait for the
 * network, and the {@link ReadWatch} may give a burst of calls to a second thread.
 */
final class LinkInput extends BufferedInputStream {
  LinkInput(InputStream in, int size) {
    super(in, size);
  }

  /** Bytes read from the socket and not yet consumed (reading thread only). */
  int buffered() {
    return count - pos;
  }

  /**
   * Whether the next frame, length field included, is in the buffer. Exact on the reading thread;
   * from another thread a guess from fields the reading thread changes meanwhile, made safely (a
   * stale answer only hands reading on sooner or later).
   */
  boolean holdsWholeFrame() {
    return wholeFrame(buf, pos, count);
  }

  private static boolean wholeFrame(byte[] b, int p, int c) {
    if (b == null || p < 0 || c > b.length || c - p < 4) {
      return false; // also a torn read by another thread
    }
    int length = ((b[p] & 0xff) << 24) | ((b[p + 1] & 0xff) << 16) | ((b[p + 2] & 0xff) << 8)
        | (b[p + 3] & 0xff);
    return length >= 0 && length <= c - p - 4;
  }
}
