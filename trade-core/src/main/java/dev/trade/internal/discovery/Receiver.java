package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ProtocolFamily;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BiConsumer;

/**
 * The listening half of {@link Discovery}: checks the group's datagrams, and the answers other
 * containers send straight to this one's sending sockets, and passes announcements to the
 * listener. The datagrams are read by a {@link GroupSocket}, whose one thread reads for every
 * receiver of this JVM on the same group and hands each datagram to each receiver ({@link #offer});
 * a receiver handles its datagrams in order on its own executor (its container's timer). A packet
 * is checked (HMAC, format) once for all the receivers of one system there, and each receiver then
 * applies its own checks (its own announcements, replays).
 *
 * <p>Why not on the reading thread, as before: with 25 containers in a JVM of 100 starting, that
 * one thread ran 14-22 s behind the announcements, and the kernel dropped a fifth of the datagrams
 * for want of room in the socket's buffer. Its own work was small (about 0.1 ms of CPU per
 * datagram for all 25); what held it up were the hand-offs each listener makes (a dial starts a
 * thread, a choice wakes a timer), each a wait for a core on a loaded machine, one container after
 * the other (docs/benchmarks-log.md, "100 containers").
 *
 * <p>Shaped like JGroups' MPING. A bad packet is counted and skipped, never fatal. Thread-safe;
 * the replay table and the log limiter are confined to the delivering thread (one at a time).
 */
final class Receiver {
  /** Sees what the receiver does with each datagram; for tests. Called where it handles them. */
  interface Observer {
    Observer NONE = new Observer() {};

    default void dropped(Reason reason) {}

    /** A datagram discarded unread because listening is off. */
    default void ignored() {}
  }

  /**
   * One datagram's check, done once for every receiver with the same system id and key, whichever
   * of them handles the datagram first. Safe for concurrent use.
   */
  static final class Decoded {
    private String systemId;
    private byte[] key;
    private Announcement result;
    private BadPacketException failure;

    synchronized Announcement decode(byte[] packet, int len, String systemId, byte[] key,
        Signer signer) throws BadPacketException {
      if (this.key == null || !this.systemId.equals(systemId) || !Arrays.equals(this.key, key)) {
        this.systemId = systemId;
        this.key = key;
        this.result = null;
        this.failure = null;
        try {
          result = Packets.decode(packet, len, systemId, signer);
        } catch (BadPacketException e) {
          failure = e;
        }
      }
      if (failure != null) {
        throw failure;
      }
      return result;
    }
  }

  private static final Logger LOG = System.getLogger(Discovery.class.getName());
  private static final long CLOSE_WAIT_MILLIS = 2000;
  /**
   * The most datagrams that may wait for this receiver's executor; more are dropped as
   * {@link Reason#BACKLOG}. A socket's receive buffer holds about 200 announcements; this bounds
   * the memory a stalled container holds (the waiting packets are shared by the JVM's receivers).
   */
  static final int MAX_WAITING = 1024;
  /** Datagrams handled per task, so that the executor's other tasks (heartbeats) take turns. */
  private static final int PER_TASK = 64;

  /** A datagram handed over by the reading thread. */
  private record Waiting(byte[] packet, InetSocketAddress from, Decoded decoded) {}

  private final Executor handler;
  private final Queue<Waiting> inbox = new ConcurrentLinkedQueue<>();
  private final AtomicInteger waiting = new AtomicInteger();
  /** Whether a task to handle the inbox is queued or running on {@link #handler}. */
  private final AtomicBoolean handling = new AtomicBoolean();
  /** Datagrams dropped since the handler last looked, the inbox being full; and the last sender. */
  private final AtomicLong overflowed = new AtomicLong();
  private volatile InetSocketAddress overflowedFrom;

  private final List<DatagramChannel> answers;
  private final String systemId;
  private final String containerId;
  private final byte[] key;
  private final Signer signer; // delivering thread only
  private final Discovery.Listener listener;
  private final BiConsumer<Announcement, InetSocketAddress> newSender;
  private final Observer observer;
  private final ReplayGuard replay;
  private final Drops drops;
  private final LongAdder ignored = new LongAdder();
  /** Held while a datagram is delivered: close waits for a delivery in progress. */
  private final ReentrantLock delivering = new ReentrantLock();
  private volatile boolean on;
  private volatile boolean closed;
  private GroupSocket socket; // guarded by this

  /**
   * @param answers the sending channels, where answers to this container's announcements arrive;
   *     read while this receiver listens, closed by their owner
   * @param newSender told (on {@code handler}) of an accepted announcement from a container not
   *     heard before, and its source
   * @param replay this receiver's own: it uses it from its handling only
   * @param handler where this receiver handles its datagrams, one task at a time (a
   *     single-threaded executor: the checks, the listener and {@code newSender} run there)
   */
  Receiver(List<DatagramChannel> answers, String systemId, String containerId, byte[] key,
      Discovery.Listener listener, BiConsumer<Announcement, InetSocketAddress> newSender,
      Observer observer, ReplayGuard replay, Duration reportInterval, boolean on,
      Executor handler) {
    this.handler = handler;
    this.answers = List.copyOf(answers);
    this.systemId = systemId;
    this.containerId = containerId;
    this.key = key.clone();
    this.signer = new Signer(key);
    this.listener = listener;
    this.newSender = newSender;
    this.observer = observer;
    this.replay = replay;
    this.drops = new Drops(LOG, systemId, reportInterval.toNanos());
    this.on = on;
  }

  /**
   * Starts listening to {@code target} on {@code interfaces}, sharing the socket with the other
   * receivers of this JVM there.
   *
   * @throws IOException if the port cannot be bound or the group not joined (see
   *     {@link Sockets#receiver}), or the answer channels cannot be read
   */
  synchronized void start(ProtocolFamily family, InetSocketAddress target,
      List<NetworkInterface> interfaces) throws IOException {
    socket = GroupSocket.join(family, target, interfaces, this, answers);
  }

  void setOn(boolean on) {
    this.on = on;
  }

  boolean isOn() {
    return on;
  }

  Map<Reason, Long> dropCounts() {
    return drops.counts();
  }

  long ignoredCount() {
    return ignored.sum();
  }

  /**
   * Stops listening. Once it has returned the listener is not called any more, unless this is called
   * from the listener itself, or a delivery in progress takes longer than 2 s (which is logged).
   * Idempotent.
   */
  void close() {
    closed = true;
    synchronized (this) {
      if (socket != null) {
        socket.leave(this);
        socket = null;
      }
    }
    if (delivering.isHeldByCurrentThread()) {
      return;
    }
    try {
      if (delivering.tryLock(CLOSE_WAIT_MILLIS, TimeUnit.MILLISECONDS)) {
        delivering.unlock();
      } else {
        LOG.log(Level.WARNING, "Discovery of {0} is still delivering an announcement after {1} ms:"
            + " is the discovery listener blocked?", containerId, CLOSE_WAIT_MILLIS);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  /**
   * Hands over one datagram from the group ({@code decoded} shared with the other receivers it
   * goes to) or from this receiver's answer channels ({@code decoded} null), {@code packet} being
   * exactly its bytes and never changed after. Called by the group's thread; returns at once.
   */
  void offer(byte[] packet, InetSocketAddress from, Decoded decoded) {
    if (closed) {
      return;
    }
    if (waiting.incrementAndGet() > MAX_WAITING) {
      waiting.decrementAndGet();
      overflowedFrom = from;
      overflowed.incrementAndGet();
    } else {
      inbox.add(new Waiting(packet, from, decoded));
    }
    if (handling.compareAndSet(false, true)) {
      submit();
    }
  }

  private void submit() {
    try {
      handler.execute(this::handleWaiting);
    } catch (RejectedExecutionException e) {
      // The container is closing: what waits is never handled.
      handling.set(false);
      inbox.clear();
      waiting.set(0);
    }
  }

  /** Handles up to {@link #PER_TASK} waiting datagrams, then queues itself again if more wait. */
  private void handleWaiting() {
    try {
      handleSome();
    } finally {
      handling.set(false);
      // A datagram offered after the last poll found the flag still set and queued no task.
      if ((!inbox.isEmpty() || overflowed.get() > 0) && handling.compareAndSet(false, true)) {
        submit();
      }
    }
  }

  private void handleSome() {
    long dropped = overflowed.getAndSet(0);
    if (dropped > 0) {
      try {
        backlogDropped(dropped, overflowedFrom);
      } catch (RuntimeException e) {
        LOG.log(Level.WARNING, "A discovery receiver failed on counting dropped datagrams", e);
      }
    }
    for (int i = 0; i < PER_TASK; i++) {
      Waiting w = inbox.poll();
      if (w == null) {
        break;
      }
      waiting.decrementAndGet();
      try {
        received(w);
      } catch (RuntimeException e) {
        // Its failure is its own: the next datagram is handled all the same.
        LOG.log(Level.WARNING, "A discovery receiver failed on a datagram from " + w.from()
            + "; delivery goes on", e);
      }
    }
  }

  private void backlogDropped(long n, InetSocketAddress from) {
    delivering.lock();
    try {
      BadPacketException e = new BadPacketException(Reason.BACKLOG, n + " datagram(s) dropped"
          + " unread: " + MAX_WAITING + " were waiting to be handled (is the JVM overloaded?)");
      for (long i = 0; i < n; i++) {
        drops.record(e, from.getAddress(), System.nanoTime());
        observer.dropped(Reason.BACKLOG);
      }
    } finally {
      delivering.unlock();
    }
  }

  /** Checks one datagram handed over by {@link #offer}, then passes it on or drops it. */
  private void received(Waiting w) {
    delivering.lock();
    try {
      if (closed) {
        return;
      }
      if (!on) {
        ignored.increment();
        observer.ignored();
        return;
      }
      handle(w.packet(), w.packet().length, w.from(), w.decoded(), w.decoded() == null);
    } finally {
      delivering.unlock();
    }
  }

  /**
   * Checks one datagram from the group, then passes it on or drops it. Delivering thread only (or
   * tests).
   */
  void handle(byte[] packet, int len, InetSocketAddress from) {
    handle(packet, len, from, null, false);
  }

  private void handle(byte[] packet, int len, InetSocketAddress from, Decoded decoded,
      boolean answer) {
    Announcement a;
    boolean isNew;
    try {
      a = decoded == null ? Packets.decode(packet, len, systemId, signer)
          : decoded.decode(packet, len, systemId, key, signer);
      if (a.containerId().equals(containerId)) {
        throw new BadPacketException(Reason.OWN, "our own announcement");
      }
      isNew = replay.check(a, System.currentTimeMillis());
    } catch (BadPacketException e) {
      drops.record(e, from.getAddress(), System.nanoTime());
      observer.dropped(e.reason());
      return;
    }
    LOG.log(Level.DEBUG, "Heard {0} from {1}", a, from);
    if (isNew) {
      newSender.accept(a, from);
    }
    try {
      listener.heard(a, from.getAddress(), answer);
    } catch (RuntimeException e) {
      LOG.log(Level.WARNING, "The discovery listener failed on " + a + "; discovery goes on", e);
    }
  }
}
