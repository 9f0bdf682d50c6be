package dev.trade.internal.net.link;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.concurrent.TimeUnit;

/**
 * A link's input: reads its frames ({@link #readFrame}), checking, opening and judging each, and
 * tells whether the next frame has arrived whole: then the reading thread can go on without
 * blocking, so it may hold back replies until it must wait for the network, and the
 * {@link ReadWatch} may give a burst of calls to a second thread. A frame that is a copy of what
 * the container has is judged and dropped inside the buffer, without being copied out.
 *
 * <p>Read by one thread at a time (whoever reads the link), except for {@link #holdsWholeFrame}.
 */
final class LinkInput extends BufferedInputStream {
  private static final int READ_CHUNK = 64 * 1024;
  /** What a frame's payload is first read into: the whole of most frames. */
  static final int FIRST_PAYLOAD = 64 * 1024;

  /** A frame read whole. */
  record Frame(int type, byte[] payload) {}

  /** Says whether a frame is a copy to drop: {@code len} bytes of {@code buf} from {@code off}. */
  interface Judge {
    boolean isStale(int type, byte[] buf, int off, int len);
  }

  /** Why a link ends because of what its peer sent (the message says it). */
  static final class Broken extends IOException {
    Broken(String why) {
      super(why);
    }
  }

  private final DataInputStream data = new DataInputStream(this);
  private final Socket socket;
  private final String peerName;
  private final int maxFrame;
  private final FrameCipher cipher;
  private final Judge judge;
  private final Runnable arrived;

  /**
   * @param socket the link's, read through {@code in}: {@link #fillWithin} times its reads out
   * @param cipher opens the peer's frames; null when the link is not encrypted
   * @param arrived runs whenever bytes arrive: a peer whose bytes keep coming is not silent
   */
  LinkInput(Socket socket, InputStream in, int size, String peerName, int maxFrame,
      FrameCipher cipher, Judge judge, Runnable arrived) {
    super(in, size);
    this.socket = socket;
    this.peerName = peerName;
    this.maxFrame = maxFrame;
    this.cipher = cipher;
    this.judge = judge;
    this.arrived = arrived;
  }

  /**
   * Reads the next frame, blocking until it is whole.
   *
   * @return the frame, or null if it was a copy and is dropped
   * @throws Broken if the peer closed the connection or sent what it must not
   * @throws IOException if reading failed
   */
  Frame readFrame() throws IOException {
    int length;
    try {
      length = data.readInt();
    } catch (EOFException e) {
      throw new Broken("connection closed by " + peerName);
    }
    int overhead = cipher == null ? 0 : FrameCipher.TAG_BYTES;
    if (length < 2 + overhead || length > maxFrame + overhead) {
      throw new Broken("malformed frame from " + peerName + ": length " + length
          + " (limit MAXFRAMESIZE=" + maxFrame + ")");
    }
    int version;
    int type;
    byte[] payload;
    boolean judged = false; // whether the judge has said the frame is not stale
    if (cipher == null) {
      version = data.readUnsignedByte();
      type = data.readUnsignedByte();
      int size = length - 2;
      if (version == Wire.VERSION && buffered() >= size) {
        // Most flood frames are copies: judged in the buffer, they are dropped uncopied.
        if (judge.isStale(type, buf, pos, size)) {
          consume(size);
          arrived.run();
          return null;
        }
        judged = true;
      }
      payload = readPayload(size);
    } else {
      byte[] sealed = readPayload(length);
      byte[] body;
      try {
        body = cipher.open(sealed);
      } catch (GeneralSecurityException e) {
        throw new Broken("frame from " + peerName + " failed decryption (altered or out of order)");
      }
      version = body[0] & 0xff;
      type = body[1] & 0xff;
      payload = Arrays.copyOfRange(body, 2, body.length);
    }
    if (version != Wire.VERSION) {
      throw new Broken("frame of protocol version " + version + " from " + peerName);
    }
    arrived.run();
    if (!judged && judge.isStale(type, payload, 0, payload.length)) {
      return null;
    }
    return new Frame(type, payload);
  }

  /**
   * Reads a frame's payload into a new array, running {@code arrived} whenever bytes arrive: a
   * large frame on a slow link can take longer than FAILURETIMEOUT. The array grows with the bytes
   * that arrive, doubling, never ahead of them by more than it holds: a peer that claims a frame of
   * MAXFRAMESIZE and sends a few bytes makes this allocate {@link #FIRST_PAYLOAD} bytes, not the
   * claim (six links claiming 12 MiB each ran a 64 MiB container out of memory).
   */
  private byte[] readPayload(int size) throws IOException {
    byte[] payload = new byte[Math.min(size, FIRST_PAYLOAD)];
    int done = 0;
    while (done < size) {
      if (done == payload.length) {
        payload = Arrays.copyOf(payload, (int) Math.min(size, 2L * payload.length));
      }
      int n = read(payload, done, Math.min(READ_CHUNK, payload.length - done));
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

  /** Drops {@code n} of the {@link #buffered()} bytes unread (reading thread only). */
  private void consume(int n) {
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

  /**
   * Moves into the buffer what the socket holds already, without blocking, for a reader that must
   * not block (a caller that reads its own reply, which has a deadline).
   *
   * @return whether a whole frame is buffered now; never for a frame larger than the buffer
   */
  synchronized boolean fillWithoutBlocking() throws IOException {
    if (wholeFrame(buf, pos, count)) {
      return true;
    }
    int ready = in.available();
    if (ready <= 0) {
      return false; // nothing, or the end of the stream, which a blocking read will find
    }
    if (buf.length - count < ready) {
      compact();
    }
    int n = in.read(buf, count, Math.min(ready, buf.length - count));
    if (n > 0) {
      count += n;
    }
    return wholeFrame(buf, pos, count);
  }

  /**
   * Moves into the buffer what arrives within {@code nanos} (at least a millisecond), blocking in
   * the read: for a caller that reads its own reply and has spun long enough; the reply then wakes
   * it, not the link's thread, which would have to wake it in turn. The socket's read timeout is
   * set for this read and cleared after it: the link's thread reads without one, and never while
   * a caller does.
   *
   * @return true if a whole frame is buffered or bytes came; false if none came in time, at the end
   *     of the stream (which the link's thread reads again), and for a frame larger than the buffer
   */
  synchronized boolean fillWithin(long nanos) throws IOException {
    if (wholeFrame(buf, pos, count)) {
      return true;
    }
    compact();
    if (count == buf.length) {
      return false;
    }
    socket.setSoTimeout((int) Math.max(1, TimeUnit.NANOSECONDS.toMillis(nanos)));
    try {
      int n = in.read(buf, count, buf.length - count);
      if (n <= 0) {
        return false;
      }
      count += n;
      return true;
    } catch (SocketTimeoutException e) {
      return false;
    } finally {
      socket.setSoTimeout(0);
    }
  }

  /** Moves the unread bytes to the buffer's start, to make room; marks are never used here. */
  private void compact() {
    if (pos > 0) {
      System.arraycopy(buf, pos, buf, 0, count - pos);
      count -= pos;
      pos = 0;
    }
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
