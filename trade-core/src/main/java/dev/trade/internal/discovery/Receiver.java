package dev.trade.internal.discovery;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;

/**
 * The listening half of {@link Discovery}: one named daemon thread that reads the group's
 * datagrams, checks them and passes announcements to the listener.
 *
 * <p>Shaped like JGroups' MPING: {@link #close()} closes the channel, which unblocks
 * {@code receive()}, and the loop ends on the resulting {@link ClosedChannelException}; a bad
 * packet is counted and skipped, never fatal. Thread-safe; the replay table and the log limiter are
 * confined to the receive thread.
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

  private final DatagramChannel channel;
  private final String systemId;
  private final String containerId;
  private final byte[] key;
  private final Discovery.Listener listener;
  private final Runnable newSender;
  private final Observer observer;
  private final ReplayGuard replay;
  private final Drops drops;
  private final Thread thread;
  private final LongAdder ignored = new LongAdder();
  private volatile boolean on;
  private volatile boolean closed;

  /**
   * @param newSender run (on the receive thread) when an accepted announcement comes from a
   *     container not heard before; must be quick
   */
  Receiver(DatagramChannel channel, String systemId, String containerId, byte[] key,
      Discovery.Listener listener, Runnable newSender, Observer observer, Duration maxClockSkew,
      Duration reportInterval, boolean on, String threadName) {
    this.channel = channel;
    this.systemId = systemId;
    this.containerId = containerId;
    this.key = key;
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
   * Closes the channel and waits up to 2 s for the thread to end, unless called from it.
   * Idempotent.
   */
  void close() {
    closed = true;
    Sockets.closeQuietly(channel);
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
    while (!closed) {
      InetSocketAddress from;
      try {
        buf.clear();
        from = (InetSocketAddress) channel.receive(buf);
        failures = 0;
      } catch (ClosedChannelException e) {
        break;
      } catch (IOException | RuntimeException e) {
        // Datagram receive errors are transient; stop only if they persist, rather than spin.
        if (++failures >= MAX_CONSECUTIVE_FAILURES) {
          LOG.log(Level.ERROR, "Discovery stops listening after " + failures + " failures", e);
          break;
        }
        LOG.log(Level.WARNING, "Discovery could not receive; retrying", e);
        continue;
      }
      if (!on) {
        ignored.increment();
        observer.ignored();
        continue;
      }
      handle(buf.array(), buf.position(), from.getAddress());
    }
  }

  /** Checks one datagram, then passes it on or drops it. Receive thread only (or tests). */
  void handle(byte[] packet, int len, InetAddress from) {
    Announcement a;
    boolean isNew;
    try {
      a = Packets.decode(packet, len, systemId, key);
      if (a.containerId().equals(containerId)) {
        throw new BadPacketException(Reason.OWN, "our own announcement");
      }
      isNew = replay.check(a, System.currentTimeMillis());
    } catch (BadPacketException e) {
      drops.record(e, from, System.nanoTime());
      observer.dropped(e.reason());
      return;
    }
    LOG.log(Level.DEBUG, "Heard {0} from {1}", a, from.getHostAddress());
    if (isNew) {
      newSender.run();
    }
    try {
      listener.heard(a, from);
    } catch (RuntimeException e) {
      LOG.log(Level.WARNING, "The discovery listener failed on " + a + "; discovery goes on", e);
    }
  }
}
