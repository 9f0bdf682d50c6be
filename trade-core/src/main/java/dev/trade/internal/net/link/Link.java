package dev.trade.internal.net.link;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.net.SocketException;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;

/**
 * One authenticated connection to a neighbouring container.
 *
 * <p><b>Writing</b> combines frames ({@link LinkOutput}). <b>Reading</b> happens on one thread at a
 * time ({@link LinkReader}), which hands each frame to the {@link LinkHandler}. The handler serves
 * a call on that thread ({@link ServedCalls}); a {@link ReadWatch} moves reading to another thread
 * when a call takes longer than a tick. This class holds the link's state, sends, and closes.
 *
 * <p>This class is safe for concurrent use.
 */
public final class Link {
  /**
   * The size of a link's input and output buffers. Small: a container keeps one link per
   * neighbour, and with 100 containers on a host 2 x 64 KB per link was 12.7 MB of heap per
   * container. Frames larger than a buffer bypass it, and 8 KB still coalesces about a hundred
   * small call frames per system call.
   */
  static final int BUFFER = 8 * 1024;
  /** The GOODBYE frame: the sender is closing, or done with this link (see LinkReferee). */
  static final byte[] GOODBYE = Frames.finish(Frames.start(Wire.GOODBYE, 0));

  public final UUID peerId;
  /** {@link #peerId} as text, as link states and tables name containers. */
  public final String peerKey;
  public final String peerName;
  final boolean initiatedHere;
  /** The number its opening side gave this connection, 0 if not told (see Handshake.Peer#dial). */
  final long dial;
  /** Whether both sides exchange DIGEST, not their full state, when the link comes up. */
  public final boolean digests;
  /**
   * The largest frame (after its length field) sent over this link: our MAXFRAMESIZE, or the
   * peer's if it said in its HELLO that it accepts less. A larger frame would close the link.
   */
  public final int sendLimit;
  private final Socket socket;
  private final LinkInput input;
  /** Reads the link, on whichever thread reads it now. */
  final LinkReader reader;
  /** What is sent over the link; callers look at its room before they queue a call. */
  public final LinkOutput output;
  /** Set once the goodbye of {@link #retire} is queued. */
  private volatile boolean retired;
  /** Completed by {@link #close}, first of all. */
  private final CompletableFuture<Void> closed = new CompletableFuture<>();
  /** This link's frames that wait for the control thread. */
  public final ControlBacklog backlog = new ControlBacklog();
  /** Why the link was closed, by whoever closed it first; null while it is open. */
  private volatile String closeReason;
  // Set when the link is to close once the queued frames are written.
  private volatile String closeWhenDrained;
  /** Why a write failed, if one did: then nothing more is written, and reading ends the link. */
  private volatile String writeFailure;
  private LinkHandler handler;
  private ReadWatch watch;
  /**
   * Whether the link's thread or a caller waiting for its reply reads; such a caller counts itself
   * ({@link ReadRole#borrow}) before it sends its call.
   */
  final ReadRole role;
  private volatile ServedCalls served;
  volatile long lastReceived = System.nanoTime();
  private final Runnable arrived = () -> lastReceived = System.nanoTime();
  volatile long lastSent = System.nanoTime();
  /**
   * A heartbeat PING to this link is queued or being sent (a send may block while the peer reads
   * nothing).
   */
  volatile boolean pinging;
  /** This link's round-trip time, from the heartbeat's probes. */
  final RoundTrip roundTrip = new RoundTrip(System.nanoTime());

  /**
   * The smoothed round-trip time of this link in nanoseconds, measured by heartbeat probes the
   * peer echoes; -1 before the first echo (or always, with a peer that does not echo).
   */
  public long roundTripNanos() {
    return roundTrip.nanos();
  }

  /**
   * A caller waits for {@code reply} over this link without reading it (an asynchronous call, which
   * holds no thread): reading is not lent to callers until the reply is done, since nobody else
   * would read it.
   */
  public void awaitedWithoutReading(CompletableFuture<?> reply) {
    role.parking();
    reply.whenComplete((r, e) -> role.unparked());
  }

  public Link(Socket socket, Handshake.Peer peer, boolean initiatedHere, int maxFrame) throws IOException {
    this(socket, peer, initiatedHere, maxFrame, new ReadRole());
  }

  /** As above, with who reads the link decided by {@code role} (tests give its linger and clock). */
  Link(Socket socket, Handshake.Peer peer, boolean initiatedHere, int maxFrame, ReadRole role)
      throws IOException {
    this.role = role;
    this.socket = socket;
    this.peerId = peer.containerId();
    this.peerKey = peerId.toString();
    this.peerName = peer.name();
    this.initiatedHere = initiatedHere;
    this.dial = peer.dial();
    this.digests = peer.digests();
    this.sendLimit = peer.maxFrame() > 0 ? Math.min(maxFrame, peer.maxFrame()) : maxFrame;
    FrameCipher cipher = peer.cipher();
    this.input = new LinkInput(socket, socket.getInputStream(), BUFFER, peerName, maxFrame,
        cipher, (type, buf, off, len) -> handler.isStale(this, type, buf, off, len), arrived);
    this.reader = new LinkReader(this, input);
    this.output = new LinkOutput(new BufferedOutputStream(socket.getOutputStream(), BUFFER), cipher,
        () -> lastSent = System.nanoTime(), LinkOutput.ROOM,
        frame -> handler != null && handler.abandoned(frame));
  }

  /**
   * Starts reading on a thread of its own; {@code watch} keeps the link read while calls are
   * served.
   */
  public void start(LinkHandler handler, ReadWatch watch) {
    this.handler = handler;
    this.watch = watch;
    this.served = new ServedCalls(watch, input, () -> {
      if (!watch.read(() -> reader.loop(null))) {
        close("container closing");
      }
    });
    Thread t = new Thread(() -> reader.loop(null), "trade-reader-" + peerName);
    t.setDaemon(true);
    t.start();
  }

  /** Serves a call on the reading thread that read it; see {@link ServedCalls#serveHere}. */
  public boolean serveHere(Runnable call) {
    return served.serveHere(call);
  }

  /**
   * Whether the current thread serves a call that came over this link: a call it makes over the
   * link then calls back the peer that waits for it (see {@link ReplyWait}).
   */
  boolean servesCallOnThisThread() {
    ServedCalls s = served;
    return s != null && s.servesOne();
  }

  /** How many of this link's calls are served by threads that no longer read it. */
  public int servedElsewhere() {
    ServedCalls s = served;
    return s == null ? 0 : s.servedElsewhere();
  }

  /** The {@link ReadWatch}'s look at this link; see {@link ServedCalls#look}. */
  boolean watch() {
    ServedCalls s = served;
    return s != null && s.look();
  }

  /**
   * Sends one complete frame (header included). Returns once the frame is written or handed to the
   * thread that is writing.
   *
   * @throws IOException when the link is closed or the write fails (see {@link #writeFailed})
   */
  public void send(byte[] frame) throws IOException {
    queue(frame);
    sendQueued();
  }

  /** As {@link #send}, for a CALL another container made ({@link LinkOutput#offerPassedOn}). */
  public void passOn(byte[] call) throws IOException {
    checkOpen();
    output.offerPassedOn(call);
    checkNotAfterGoodbye(call);
    sendQueued();
  }

  private void sendQueued() throws IOException {
    if (!output.leftForBurst()) {
      writeQueued();
    }
  }

  /**
   * Queues one complete frame without writing it: {@link #flushQueued()}, or the next
   * {@link #send}, writes it with whatever else is queued then, in one system call. For a thread
   * that sends many frames over many links in a row (the control thread's floods).
   *
   * @throws IOException when the link is closed
   */
  public void queue(byte[] frame) throws IOException {
    checkOpen();
    output.offer(frame);
    checkNotAfterGoodbye(frame);
  }

  /**
   * A frame queued while the link was retired may be behind the GOODBYE, which nothing follows
   * ({@link LinkOutput#write}): it is taken back, and the sender told as if the link were closed.
   * (A frame queued after the retirement is seen here to be so: its sender read {@link #retired}
   * after queueing it, and the retiring thread set it before it queued the GOODBYE.)
   */
  private void checkNotAfterGoodbye(byte[] frame) throws IOException {
    if (retired && output.withdraw(frame)) {
      throw new IOException("link to " + peerName + " is closed (replaced)");
    }
  }

  private void checkOpen() throws IOException {
    if (isClosed() || retired) {
      throw new IOException("link to " + peerName + " is closed" + (retired ? " (replaced)" : ""));
    }
  }

  /**
   * Sends GOODBYE as the last frame of this link: later sends fail as on a closed link, so that a
   * reply to a call that came over it goes over the link that replaced it.
   */
  void retire() throws IOException {
    checkOpen();
    retired = true;
    output.offer(GOODBYE);
    sendQueued();
  }

  /** Writes what {@link #queue} queued, unless another thread is writing: that one writes it. */
  public void flushQueued() throws IOException {
    writeQueued();
  }

  /**
   * Ends a burst and writes what was sent during it (whoever reads, when nothing whole is left to
   * hand out: before the link's thread blocks in a read, or while a caller waits on). Guarded
   * like a served call: should the peer not read (its reader busy writing to us), the watch hands
   * reading to another thread after a tick, so two links that write to each other cannot wait for
   * each other for ever.
   *
   * @return true if this thread still reads the link
   */
  boolean endBurst() {
    if (!output.endBurst()) {
      return true;
    }
    return serveHere(() -> {
      try {
        writeQueued();
      } catch (IOException e) {
        // The write failed: reading goes on to the end the peer left (see writeFailed).
      }
    });
  }

  /**
   * Writes what is queued (see {@link LinkOutput#write(boolean)}), or hands the rest to a worker
   * once it has written for others a while; see {@link #writeFailed}.
   */
  private void writeQueued() throws IOException {
    ReadWatch w = watch;
    if (writeQueued(true) && (w == null || !w.read(this::writeRest))) {
      writeQueued(false); // no worker: the container is closing
    }
  }

  /** On a worker: writes all that is queued; writeFailed sees to a failure. */
  private void writeRest() {
    try {
      writeQueued(false);
    } catch (IOException e) {
      // Seen to by writeFailed.
    }
  }

  /** Whether the write stopped with frames left ({@code budgeted}); see {@link #writeQueued()}. */
  private boolean writeQueued(boolean budgeted) throws IOException {
    boolean left;
    try {
      left = output.write(budgeted);
    } catch (IOException e) {
      writeFailed("write failed: " + e.getMessage());
      throw e;
    }
    if (left) {
      return true;
    }
    String closing = closeWhenDrained;
    if (closing != null && output.drained()) {
      close(closing);
    }
    return false;
  }

  /**
   * A write failed, mostly because the peer closed the connection, perhaps right after its
   * goodbye, which may still wait to be read. Closing the socket now would drop it, and an orderly
   * leave would count as a failure. So the link only stops writing and counts as closed to senders;
   * its reading reads what the peer sent last, then finds the end and closes it with the reason it
   * read. Should the peer be silent instead, the heartbeat closes the link.
   */
  private void writeFailed(String why) {
    writeFailure = why;
    try {
      socket.shutdownOutput();
    } catch (IOException e) {
      close(why);
    }
  }

  /**
   * Whether {@link #close} closed the socket; a failed write alone does not (see
   * {@link #isClosed}): reading goes on to the end the peer left.
   */
  boolean socketClosed() {
    return closed.isDone();
  }

  /** The socket's read timeout in ms, 0 for none (for tests: the link's thread reads without). */
  int readTimeout() throws SocketException {
    return socket.getSoTimeout();
  }

  /** Why the link was closed, by whoever closed it first; null while it is open. */
  String closeReason() {
    return closeReason;
  }

  /** The handler given to {@link #start}, which the reader hands frames to. */
  LinkHandler handler() {
    return handler;
  }

  /** The watch given to {@link #start}, which the reader hands reading to. */
  ReadWatch readWatch() {
    return watch;
  }

  /** Whether the link is closed, or can no longer be written to: then it is about to close. */
  public boolean isClosed() {
    return closed.isDone() || writeFailure != null;
  }

  /** Closes the link once the frames already handed to {@link #send} are written. */
  public void closeAfterSending(String reason) {
    closeWhenDrained = reason;
    try {
      writeQueued(); // closes once nothing is queued and nobody writes
    } catch (IOException e) {
      close(reason); // nothing more can be sent
    }
  }

  /**
   * Says GOODBYE and closes the link once that is written: its container closes, and the peer sees
   * an orderly leave (also over a link whose handshake finished meanwhile). Nothing is done for a
   * link closed or closing already.
   */
  public void leave() {
    if (closeWhenDrained != null || isClosed()) {
      return;
    }
    try {
      send(GOODBYE);
      closeAfterSending("container closing");
    } catch (IOException e) {
      close("container closing");
    }
  }

  /** Closes the socket (which also ends the reader thread); idempotent. */
  public void close(String reason) {
    if (closed.complete(null)) {
      closeReason = reason;
      try {
        socket.close();
      } catch (IOException ignored) {
        // Closing is best effort; the reader notices either way.
      }
      role.closing(); // a thread that lent reading takes it back, and ends it
      output.wakeRoomWaiters(); // their calls fail at once, not at their deadlines
    }
  }

  /** Completes when the link is closed (its reader may still be ending). */
  public CompletableFuture<Void> whenClosed() {
    return closed.copy(); // completing the copy does not close the link
  }

  @Override
  public String toString() {
    return "Link[" + peerName + " " + peerId + (initiatedHere ? " out" : " in") + "]";
  }
}
