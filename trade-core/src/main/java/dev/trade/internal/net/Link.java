package dev.trade.internal.net;

import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.security.GeneralSecurityException;
import java.util.Arrays;
import java.util.Queue;
import java.util.UUID;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One authenticated connection to a neighbouring container.
 *
 * <p><b>Writing</b> combines frames: a sender that finds the socket idle writes its frame itself
 * (no thread hand-off on the latency path); senders that arrive while a write is in progress only
 * queue their frame, and the writing thread drains the queue before it flushes, so concurrent calls
 * share system calls. <b>Reading</b> happens on one thread at a time, which hands each frame to the
 * {@link Handler}. The handler serves a call on that thread ({@link #serveHere}); a {@link ReadWatch}
 * moves reading to another thread when a call takes longer than a tick. Frames the reading thread
 * sends while the next frame is already buffered (replies to a burst of calls) wait until it has
 * served that burst, and then leave with one system call.
 *
 * <p>This class is safe for concurrent use.
 */
final class Link {
  private static final int BUFFER = 8 * 1024;
  /** Receives what a link reads; called on the thread that is reading the link. */
  interface Handler {
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

    void closed(Link link, String reason);
  }

  /** The link whose call the current thread serves on that link's reading thread, if any. */
  private static final ThreadLocal<Link> SERVING = new ThreadLocal<>();

  final UUID peerId;
  /** {@link #peerId} as text, as link states and tables name containers. */
  final String peerKey;
  final String peerName;
  final boolean initiatedHere;
  /** Whether both sides exchange DIGEST, not their full state, when the link comes up. */
  final boolean digests;
  private final Socket socket;
  private final DataInputStream in;
  private final LinkInput input;
  private final OutputStream out;
  private final int maxFrame;
  private final FrameCipher cipher;
  private final Queue<byte[]> queue = new ConcurrentLinkedQueue<>();
  private final AtomicBoolean writing = new AtomicBoolean();
  private final AtomicBoolean closed = new AtomicBoolean();
  /** Why the link was closed, by whoever closed it first; null while it is open. */
  private volatile String closeReason;
  // Set when the link is to close once the queued frames are written.
  private volatile String closeWhenDrained;
  /** Whether the reading thread is handing out frames read together with more; see send. */
  private volatile boolean burst;
  /** Whether a frame was sent, and perhaps left for the end of a burst, since the last look. */
  private volatile boolean deferred;
  private Handler handler;
  private ReadWatch watch;
  // The thread in the read loop; null while reading moves to another one.
  private volatile Thread reader;
  // Odd while the reading thread serves a call; each call and each hand-off counts one up, so a
  // stale value never matches a later call.
  private final AtomicLong work = new AtomicLong();
  // The thread whose call 'work' counts while it is odd.
  private volatile Thread worker;
  // What the watch saw at its last look; read and written by the watch thread only.
  private long watchSeen;
  volatile long lastReceived = System.nanoTime();
  private final Runnable arrived = () -> lastReceived = System.nanoTime();
  volatile long lastSent = System.nanoTime();
  /**
   * A heartbeat PING to this link is queued or being sent (a send may block while the peer reads
   * nothing).
   */
  volatile boolean pinging;

  Link(Socket socket, Handshake.Peer peer, boolean initiatedHere, int maxFrame) throws IOException {
    this.socket = socket;
    this.peerId = peer.containerId();
    this.peerKey = peerId.toString();
    this.peerName = peer.name();
    this.initiatedHere = initiatedHere;
    this.digests = peer.digests();
    this.maxFrame = maxFrame;
    this.cipher = peer.cipher();
    // Small buffers: a container keeps one link per neighbour, and with 100 containers on a host
    // 2 x 64 KB per link was 12.7 MB of heap per container. Frames larger than a buffer bypass it
    // (BufferedInput/OutputStream read and write those directly), and 8 KB still coalesces about
    // a hundred small call frames per system call.
    this.input = new LinkInput(socket.getInputStream(), BUFFER);
    this.in = new DataInputStream(input);
    this.out = new BufferedOutputStream(socket.getOutputStream(), BUFFER);
  }

  /** Starts reading on a thread of its own; {@code watch} keeps the link read while calls are served. */
  void start(Handler handler, ReadWatch watch) {
    this.handler = handler;
    this.watch = watch;
    Thread t = new Thread(this::readLoop, "trade-reader-" + peerName);
    t.setDaemon(true);
    t.start();
  }

  /**
   * Serves a call on the thread that read it (called by the handler, on the reading thread): the call
   * runs without another thread waking up first, and its reply can leave with those of the calls
   * read with it. Should the call take longer than a tick of the {@link ReadWatch}, or wait for a
   * remote reply ({@link #releaseReading}), reading goes on in another thread meanwhile.
   *
   * @return true if this thread still reads the link, false if reading went on elsewhere (then
   *     this thread leaves the read loop)
   */
  boolean serveHere(Runnable call) {
    worker = Thread.currentThread();
    long stamp = work.incrementAndGet();
    watch.serving();
    SERVING.set(this);
    try {
      call.run();
    } finally {
      SERVING.set(null);
    }
    return work.compareAndSet(stamp, stamp + 1);
  }

  /**
   * Called by a thread that is about to wait for a remote reply: if it is serving a call on a
   * link's reading thread, reading goes on elsewhere at once, since the reply may come over that very
   * link.
   */
  static void releaseReading() {
    Link link = SERVING.get();
    if (link != null) {
      SERVING.set(null);
      long stamp = link.work.get();
      if (link.worker == Thread.currentThread()) {
        link.handOff(stamp);
      }
    }
  }

  /**
   * The watch's look at this link (watch thread only). Hands reading on when the reading thread has
   * served the same call since the last look (a slow call), or serves a call while whole frames
   * wait behind it (a burst that another core can help with). Either costs one thread wake-up,
   * at most once per tick.
   *
   * @return whether the link served any call since the last look
   */
  boolean watch() {
    long stamp = work.get();
    boolean serving = (stamp & 1) == 1;
    boolean changed = stamp != watchSeen;
    if (serving && (!changed || input.holdsWholeFrame())) {
      handOff(stamp);
    }
    watchSeen = stamp;
    return changed || serving;
  }

  /** Moves reading to another thread if {@code stamp} is still the call being served. */
  private void handOff(long stamp) {
    if ((stamp & 1) == 1 && work.compareAndSet(stamp, stamp + 1)) {
      reader = null;
      if (!watch.read(this::readLoop)) {
        close("container closing");
      }
    }
  }

  /**
   * Sends one complete frame (header included). Returns once the frame is written or handed to the
   * thread that is writing.
   *
   * @throws IOException when the link is closed or the write fails (the link is then closed)
   */
  void send(byte[] frame) throws IOException {
    queue(frame);
    deferred = true; // before looking at burst, see endBurst
    if (burst) {
      // The reading thread hands out frames read together (calls to serve here, or replies that
      // wake callers who call again at once): it writes what they send, in one system call,
      // before it reads again. Whoever reads after it sees the same, as a burst ends before then.
      return;
    }
    deferred = false;
    writeQueued();
  }

  /**
   * Queues one complete frame without writing it: {@link #flushQueued()}, or the next
   * {@link #send}, writes it with whatever else is queued then, in one system call. For a thread
   * that sends many frames over many links in a row (the control thread's floods).
   *
   * @throws IOException when the link is closed
   */
  void queue(byte[] frame) throws IOException {
    if (closed.get()) {
      throw new IOException("link to " + peerName + " is closed");
    }
    queue.offer(frame);
  }

  /** Writes what {@link #queue} queued, unless another thread is writing: that one writes it. */
  void flushQueued() throws IOException {
    writeQueued();
  }

  /**
   * Ends a burst and writes what was sent during it (reading thread, before it may block in a
   * read). Guarded like a served call: should the peer not read (its reader busy writing to us),
   * the watch hands reading to another thread after a tick, so two links that write to each other
   * cannot wait for each other for ever.
   *
   * @return true if this thread still reads the link
   */
  private boolean endBurst() {
    burst = false; // before looking at deferred: a sender that saw burst true set it before this
    if (!deferred) {
      return true; // what others queued (the control thread's floods) they write themselves
    }
    deferred = false;
    return serveHere(() -> {
      try {
        writeQueued();
      } catch (IOException e) {
        // writeQueued closed the link; the read loop ends with its reason.
      }
    });
  }

  /**
   * Writes and flushes every queued frame, unless another thread is writing: that one writes them.
   * No lock: with many callers on one link, a lock here made them queue for it and sleep.
   */
  private void writeQueued() throws IOException {
    while (!queue.isEmpty() && writing.compareAndSet(false, true)) {
      try {
        byte[] next;
        while ((next = queue.poll()) != null) {
          // Sealing here, in write order, keeps the cipher's frame counter in step with the wire.
          out.write(cipher == null ? next : cipher.seal(next));
        }
        out.flush();
        lastSent = System.nanoTime();
      } catch (IOException e) {
        queue.clear();
        close("write failed: " + e.getMessage());
        throw e;
      } finally {
        writing.set(false);
      }
      // A frame queued after our last poll by a sender that found us writing is ours: look again.
    }
    String closing = closeWhenDrained;
    if (closing != null && queue.isEmpty() && !writing.get()) {
      close(closing);
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
        if (!input.holdsWholeFrame() && !endBurst()) {
          return; // the flush blocked and reading went on in another thread
        }
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
        boolean judged = false; // whether the handler has said the frame is not stale
        if (cipher == null) {
          version = in.readUnsignedByte();
          type = in.readUnsignedByte();
          int size = length - 2;
          if (version == Wire.VERSION && input.buffered() >= size) {
            // Most flood frames are copies: judged in the buffer, they are dropped uncopied.
            if (handler.isStale(this, type, input.buffer(), input.position(), size)) {
              input.consume(size);
              lastReceived = System.nanoTime();
              continue;
            }
            judged = true;
          }
          payload = input.readPayload(size, arrived);
        } else {
          byte[] sealed = input.readPayload(length, arrived);
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
        if (!judged && handler.isStale(this, type, payload, 0, payload.length)) {
          continue;
        }
        burst = input.holdsWholeFrame(); // more to hand out after this one: see send
        if (!handler.frame(this, type, payload)) {
          return; // reading went on in another thread while this one served a call
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

  boolean isClosed() {
    return closed.get();
  }

  /** Closes the link once the frames already handed to {@link #send} are written. */
  void closeAfterSending(String reason) {
    closeWhenDrained = reason;
    try {
      writeQueued(); // closes once nothing is queued and nobody writes
    } catch (IOException e) {
      // writeQueued() closed the link.
    }
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
