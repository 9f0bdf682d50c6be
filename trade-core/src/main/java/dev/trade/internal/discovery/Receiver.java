package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Consumer;

/**
 * The listening half of {@link Discovery}: one named daemon thread that reads the group's
 * datagrams, and the answers other containers send straight to this one's sending sockets, checks
 * them alike and passes announcements to the listener.
 *
 * <p>Shaped like JGroups' MPING. {@link #close()} wakes the thread from its selector, and it ends;
 * a bad packet is counted and skipped, never fatal. Thread-safe; the replay table and the log
 * limiter are confined to the receive thread.
 */
final class Receiver {
  /** Sees what the receive thread does with each datagram; for tests. Called on that thread. */
  interface Observer {
    Observer NONE = new Observer() {};

    default void dropped(Reason reason) {}

    /** A datagram discarded unread because listening is off. */
    default void ignored() {}
  }

  private static final Logger LOG = System.getLogger(Discovery.class.getName());
  private static final long CLOSE_WAIT_MILLIS = 2000;
  private static final int MAX_CONSECUTIVE_FAILURES = 10;

  private final List<DatagramChannel> channels;
  private final Selector selector;
  private final String systemId;
  private final String containerId;
  private final Signer signer; // receive thread only
  private final Discovery.Listener listener;
  private final Consumer<InetSocketAddress> newSender;
  private final Observer observer;
  private final ReplayGuard replay;
  private final Drops drops;
  private final Thread thread;
  private final LongAdder ignored = new LongAdder();
  private volatile boolean on;
  private volatile boolean closed;

  /**
   * @param group the channel joined to the group; closed by {@link #close()}
   * @param answers the sending channels, where answers to this container's announcements arrive;
   *     read here, closed by their owner
   * @param newSender told (on the receive thread) the source of an accepted announcement from a
   *     container not heard before; must be quick
   * @throws IOException if the channels cannot be made non-blocking or registered with a selector
   */
  Receiver(DatagramChannel group, List<DatagramChannel> answers, String systemId,
      String containerId, byte[] key, Discovery.Listener listener,
      Consumer<InetSocketAddress> newSender, Observer observer, Duration maxClockSkew,
      Duration reportInterval, boolean on, String threadName) throws IOException {
    List<DatagramChannel> all = new ArrayList<>();
    all.add(group);
    all.addAll(answers);
    this.channels = List.copyOf(all);
    this.selector = Selector.open();
    try {
      for (DatagramChannel ch : channels) {
        ch.configureBlocking(false);
        ch.register(selector, SelectionKey.OP_READ);
      }
    } catch (IOException | RuntimeException e) {
      selector.close();
      throw e;
    }
    this.systemId = systemId;
    this.containerId = containerId;
    this.signer = new Signer(key);
    this.listener = listener;
    this.newSender = newSender;
    this.observer = observer;
    this.replay = new ReplayGuard(ReplayGuard.DEFAULT_MAX_SENDERS, maxClockSkew);
    this.drops = new Drops(LOG, systemId, reportInterval.toNanos());
    this.on = on;
    this.thread = new Thread(this::run, threadName);
    thread.setDaemon(true);
  }

  void start() {
    thread.start();
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
   * Closes the group's channel and waits up to 2 s for the thread to end, unless called from it.
   * Idempotent.
   */
  void close() {
    closed = true;
    selector.wakeup();
    Sockets.closeQuietly(channels.get(0));
    if (Thread.currentThread() == thread || !thread.isAlive()) {
      return;
    }
    try {
      thread.join(CLOSE_WAIT_MILLIS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
    if (thread.isAlive()) {
      LOG.log(Level.WARNING, "{0} did not end within {1} ms: is the discovery listener blocked?",
          thread.getName(), CLOSE_WAIT_MILLIS);
    }
  }

  private void run() {
    ByteBuffer buf = ByteBuffer.allocate(Packets.MAX_PACKET + 1); // +1: tells oversize apart
    int failures = 0;
    try (selector) {
      while (!closed) {
        try {
          selector.select();
          Iterator<SelectionKey> ready = selector.selectedKeys().iterator();
          while (ready.hasNext() && !closed) {
            DatagramChannel ch = (DatagramChannel) ready.next().channel();
            ready.remove();
            InetSocketAddress from;
            while (!closed && (from = (InetSocketAddress) ch.receive(buf.clear())) != null) {
              received(buf, from);
            }
          }
          failures = 0;
        } catch (ClosedChannelException | ClosedSelectorException e) {
          break;
        } catch (IOException | RuntimeException e) {
          // Datagram receive errors are transient; stop only if they persist, rather than spin.
          if (++failures >= MAX_CONSECUTIVE_FAILURES) {
            LOG.log(Level.ERROR, "Discovery stops listening after " + failures + " failures", e);
            break;
          }
          LOG.log(Level.WARNING, "Discovery could not receive; retrying", e);
        }
      }
    } catch (IOException e) {
      // Closing the selector at the end: nothing is left to release.
    }
  }

  private void received(ByteBuffer buf, InetSocketAddress from) {
    if (!on) {
      ignored.increment();
      observer.ignored();
      return;
    }
    handle(buf.array(), buf.position(), from);
  }

  /** Checks one datagram, then passes it on or drops it. Receive thread only (or tests). */
  void handle(byte[] packet, int len, InetSocketAddress from) {
    Announcement a;
    boolean isNew;
    try {
      a = Packets.decode(packet, len, systemId, signer);
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
      newSender.accept(from);
    }
    try {
      listener.heard(a, from.getAddress());
    } catch (RuntimeException e) {
      LOG.log(Level.WARNING, "The discovery listener failed on " + a + "; discovery goes on", e);
    }
  }
}
