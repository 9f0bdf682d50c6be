package dev.trade.internal.net;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.ArrayDeque;
import java.util.UUID;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * One authenticated connection to a neighbouring container.
 *
 * <p><b>Writing</b> combines frames: a sender that finds the socket idle writes its frame itself
 * (no thread hand-off on the latency path); senders that arrive while a write is in progress only
 * queue their frame, and the writing thread drains the queue before it flushes, so concurrent calls
 * share system calls. <b>Reading</b> happens on one thread at a time, which hands each frame to the
 * {@link Handler}; the handler may keep that thread for a call and let reading go on in another
 * ({@link #moveReading}).
 *
 * <p>This class is safe for concurrent use.
 */
final class Link {
  private static final int BUFFER = 8 * 1024;
  /** Receives what a link reads; called on the thread that is reading the link. */
  interface Handler {
    void frame(Link link, int type, byte[] payload) throws IOException;

    void closed(Link link, String reason);
  }

  private static final int READ_CHUNK = 64 * 1024;

  final UUID peerId;
  final String peerName;
  final boolean initiatedHere;
  private final Socket socket;
  private final DataInputStream in;
  private final OutputStream out;
  private final int maxFrame;
  private final FrameCipher cipher;
  private final ArrayDeque<byte[]> queue = new ArrayDeque<>();
  private final AtomicBoolean closed = new AtomicBoolean();
  /** Why the link was closed, by whoever closed it first; null while it is open. */
  private volatile String closeReason;
  // Guarded by queue.
  private boolean writing;
  // Guarded by queue: set when the link is to close once the queued frames are written.
  private String closeWhenDrained;
  private Handler handler;
  // The thread in the read loop; null while reading moves to another one.
  private volatile Thread reader;
  volatile long lastReceived = System.nanoTime();
  volatile long lastSent = System.nanoTime();

  Link(Socket socket, Handshake.Peer peer, boolean initiatedHere, int maxFrame) throws IOException {
    this.socket = socket;
    this.peerId = peer.containerId();
    this.peerName = peer.name();
    this.initiatedHere = initiatedHere;
    this.maxFrame = maxFrame;
    this.cipher = peer.cipher();
    // Small buffers: a container keeps one link per neighbour, and with 100 containers on a host
    // 2 x 64 KB per link was 12.7 MB of heap per container. Frames larger than a buffer bypass it
    // (BufferedInput/OutputStream read and write those directly), and 8 KB still coalesces about
    // a hundred small call frames per system call.
    this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), BUFFER));
    this.out = new BufferedOutputStream(socket.getOutputStream(), BUFFER);
  }

  /** Starts the reader thread. */
  void start(Handler handler) {
    this.handler = handler;
    Thread t = new Thread(this::readLoop, "trade-reader-" + peerName);
    t.setDaemon(true);
    t.start();
  }

  /**
   * Called by the handler, on the reading thread, for a frame whose work it wants to do on this
   * thread (a call to serve): reading goes on in a thread of {@code executor} at once, and this
   * thread leaves the read loop when the handler returns. The work then starts without waking
   * another thread first; only the next read waits for that wake-up, off the caller's path.
   *
   * @return false if reading stays here ({@code executor} refused), so the handler hands its work off
   */
  boolean moveReading(Executor executor) {
    reader = null;
    Thread.currentThread().setName("trade-serving-" + peerName); // no longer this link's reader
    try {
      executor.execute(this::readLoop);
      return true;
    } catch (RejectedExecutionException closing) {
      reader = Thread.currentThread();
      Thread.currentThread().setName("trade-link-" + peerName);
      return false;
    }
  }

  /**
   * Sends one complete frame (header included). Returns once the frame is written or handed to the
   * thread that is writing.
   *
   * @throws IOException when the link is closed or the write fails (the link is then closed)
   */
  void send(byte[] frame) throws IOException {
    synchronized (queue) {
      if (closed.get()) {
        throw new IOException("link to " + peerName + " is closed");
      }
      if (writing) {
        queue.add(frame);
        return;
      }
      writing = true;
    }
    byte[] next = frame;
    try {
      while (true) {
        // Sealing here, in write order, keeps the cipher's frame counter in step with the wire.
        out.write(cipher == null ? next : cipher.seal(next));
        synchronized (queue) {
          next = queue.poll();
        }
        if (next != null) {
          continue;
        }
        out.flush();
        lastSent = System.nanoTime();
        String closing;
        synchronized (queue) {
          // Frames queued during the flush are ours to write too.
          next = queue.poll();
          if (next != null) {
            continue;
          }
          writing = false;
          closing = closeWhenDrained;
        }
        if (closing != null) {
          close(closing);
        }
        return;
      }
    } catch (IOException e) {
      synchronized (queue) {
        writing = false;
        queue.clear();
      }
      close("write failed: " + e.getMessage());
      throw e;
    }
  }

  private void readLoop() {
    Thread self = Thread.currentThread();
    String ownName = self.getName();
    // Whichever thread reads the link carries its name, so thread dumps show who reads what.
    self.setName("trade-link-" + peerName);
    try {
      readFrames();
    } finally {
      self.setName(ownName);
    }
  }

  private void readFrames() {
    reader = Thread.currentThread();
    String reason = "closed";
    try {
      while (!closed.get()) {
        int length;
        try {
          length = in.readInt();
        } catch (EOFException e) {
          reason = "connection closed by " + peerName;
          break;
        }
        int overhead = cipher == null ? 0 : FrameCipher.TAG_BYTES;
        if (length < 2 + overhead || length > maxFrame + overhead) {
          reason = "malformed frame from " + peerName + ": length " + length
              + " (limit MAXFRAMESIZE=" + maxFrame + ")";
          break;
        }
        int version;
        int type;
        byte[] payload;
        if (cipher == null) {
          version = in.readUnsignedByte();
          type = in.readUnsignedByte();
          payload = readPayload(length - 2);
        } else {
          byte[] sealed = readPayload(length);
          byte[] body;
          try {
            body = cipher.open(sealed);
          } catch (GeneralSecurityException e) {
            reason = "frame from " + peerName + " failed decryption (altered or out of order)";
            break;
          }
          version = body[0] & 0xff;
          type = body[1] & 0xff;
          payload = Arrays.copyOfRange(body, 2, body.length);
        }
        if (version != Wire.VERSION) {
          reason = "frame of protocol version " + version + " from " + peerName;
          break;
        }
        lastReceived = System.nanoTime();
        handler.frame(this, type, payload);
        if (reader != Thread.currentThread()) {
          return; // reading moved on to another thread; this one served a call
        }
      }
    } catch (IOException e) {
      reason = "connection to " + peerName + " lost: " + e.getMessage();
    } catch (RuntimeException e) {
      reason = "malformed frame from " + peerName + ": " + e;
    }
    String closedHere = closeReason; // closed while we read (silence, goodbye...): that is why
    if (closedHere != null) {
      reason = closedHere;
    }
    close(reason);
    handler.closed(this, reason);
  }

  /**
   * Reads a frame's payload, noting the time whenever bytes arrive: a large frame on a slow link
   * can take longer than FAILURETIMEOUT, and a peer whose bytes keep coming is not silent.
   */
  private byte[] readPayload(int size) throws IOException {
    byte[] payload = new byte[size];
    int done = 0;
    while (done < size) {
      int n = in.read(payload, done, Math.min(READ_CHUNK, size - done));
      if (n < 0) {
        throw new EOFException("connection closed by " + peerName + " within a frame");
      }
      done += n;
      lastReceived = System.nanoTime();
    }
    return payload;
  }

  boolean isClosed() {
    return closed.get();
  }

  /** Closes the link once the frames already handed to {@link #send} are written. */
  void closeAfterSending(String reason) {
    synchronized (queue) {
      if (writing) {
        closeWhenDrained = reason;
        return;
      }
    }
    close(reason);
  }

  /** Closes the socket (which also ends the reader thread); idempotent. */
  void close(String reason) {
    if (closed.compareAndSet(false, true)) {
      closeReason = reason;
      try {
        socket.close();
      } catch (IOException ignored) {
        // Closing is best effort; the reader notices either way.
      }
    }
  }

  @Override
  public String toString() {
    return "Link[" + peerName + " " + peerId + (initiatedHere ? " out" : " in") + "]";
  }
}
