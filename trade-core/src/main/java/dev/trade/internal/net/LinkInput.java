package dev.trade.internal.net;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;

/**
 * A link's input buffer, which also tells whether the next frame has arrived whole: then the
 * reading thread can go on without blocking, so it may hold back replies until it must wait for the
 * network, and the {@link ReadWatch} may give a burst of calls to a second thread. The reading
 * thread may also look at a frame inside the buffer and drop it there ({@link #consume}), without
 * copying it out.
 */
final class LinkInput extends BufferedInputStream {
  private static final int READ_CHUNK = 64 * 1024;

  LinkInput(InputStream in, int size) {
    super(in, size);
  }

  /**
   * Reads a frame's payload into a new array, running {@code arrived} whenever bytes arrive: a
   * large frame on a slow link can take longer than FAILURETIMEOUT, and a peer whose bytes keep
   * coming is not silent.
   */
  byte[] readPayload(int size, Runnable arrived) throws IOException {
    byte[] payload = new byte[size];
    int done = 0;
    while (done < size) {
      int n = read(payload, done, Math.min(READ_CHUNK, size - done));
      if (n < 0) {
        throw new EOFException("connection closed within a frame");
      }
      done += n;
      arrived.run();
    }
    return payload;
  }

  /** Bytes read from the socket and not yet consumed (reading thread only). */
  int buffered() {
    return count - pos;
  }

  /** The buffer: {@link #buffered()} bytes from {@link #position()} on (reading thread only). */
  byte[] buffer() {
    return buf;
  }

  /** Where the unconsumed bytes start in {@link #buffer()} (reading thread only). */
  int position() {
    return pos;
  }

  /** Drops {@code n} of the {@link #buffered()} bytes unread (reading thread only). */
  void consume(int n) {
    if (n < 0 || n > count - pos) {
      throw new IllegalArgumentException(n + " of " + (count - pos) + " buffered bytes");
    }
    pos += n;
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
