package dev.trade.internal.discovery;

import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ProtocolFamily;
import java.nio.ByteBuffer;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.DatagramChannel;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * The socket that receives a multicast group's datagrams, and the one thread that reads it, shared
 * by every {@link Receiver} of this JVM with the same group, port and interfaces. Each datagram
 * the kernel delivers wakes a thread: with one socket per container, 25 containers in a JVM woke
 * 25 threads and checked every HMAC 25 times for each announcement of a system of 100. The
 * thread also reads each receiver's own sending sockets, where answers to its announcements
 * arrive, and hands those to that receiver alone. It only reads: each receiver handles what it is
 * handed on its own executor ({@link Receiver#offer}), so that no container's handling holds up
 * the others'.
 *
 * <p>Opened by the first {@link #join}, closed (socket and thread) by the last {@link #leave}, and
 * only then: the receivers attached have no other ear. A receiver that fails on a datagram does
 * not stop the others, and a socket that fails to receive is retried, ever more slowly (up to once
 * a second), until it works again. Thread-safe.
 */
final class GroupSocket {
  private static final Logger LOG = System.getLogger(Discovery.class.getName());
  /** Consecutive receive failures after which they are logged as an error, not a warning. */
  private static final int PERSISTENT_FAILURES = 10;
  /** The longest pause between two attempts to receive while receiving keeps failing. */
  private static final long MAX_PAUSE_NANOS = TimeUnit.SECONDS.toNanos(1);
  /** The open ones, by family, group, port and interfaces. Guarded by itself. */
  private static final Map<List<Object>, GroupSocket> OPEN = new HashMap<>();

  private final List<Object> key;
  private final DatagramChannel group;
  private final Selector selector;
  private final List<Receiver> receivers = new CopyOnWriteArrayList<>();
  /** Each receiver's answer channels' keys. Guarded by OPEN. */
  private final Map<Receiver, List<SelectionKey>> answerKeys = new HashMap<>();
  private final Thread thread;
  private volatile boolean closed;

  private GroupSocket(List<Object> key, DatagramChannel group, Selector selector, String name) {
    this.key = key;
    this.group = group;
    this.selector = selector;
    this.thread = new Thread(this::run, name);
    thread.setDaemon(true);
  }

  /**
   * Starts delivering the group's datagrams, and those arriving on {@code answers}, to
   * {@code receiver}; opens the socket and starts the thread if no receiver of this JVM listens
   * on the same group, port and interfaces yet.
   *
   * @throws IOException if the socket cannot be opened (see {@link Sockets#receiver}) or the
   *     answer channels cannot be read without blocking
   */
  static GroupSocket join(ProtocolFamily family, InetSocketAddress target,
      List<NetworkInterface> interfaces, Receiver receiver, List<DatagramChannel> answers)
      throws IOException {
    List<Object> key = new ArrayList<>(List.of(family, target));
    for (NetworkInterface nif : interfaces) {
      key.add(nif.getIndex());
    }
    synchronized (OPEN) {
      GroupSocket g = OPEN.get(key);
      if (g == null) {
        DatagramChannel ch = Sockets.receiver(family, target, interfaces);
        Selector selector = null;
        try {
          ch.configureBlocking(false);
          selector = Selector.open();
          ch.register(selector, SelectionKey.OP_READ, null);
          g = new GroupSocket(List.copyOf(key), ch, selector,
              "trade-discovery-receive[" + Announcement.format(target) + "]");
          g.thread.start();
        } catch (IOException | RuntimeException | Error e) {
          Sockets.closeQuietly(ch);
          if (selector != null) {
            selector.close();
          }
          throw e;
        }
        OPEN.put(g.key, g);
      }
      List<SelectionKey> keys = new ArrayList<>();
      try {
        for (DatagramChannel a : answers) {
          a.configureBlocking(false);
          keys.add(a.register(g.selector, SelectionKey.OP_READ, receiver)); // at the next select
        }
      } catch (IOException | RuntimeException e) {
        keys.forEach(SelectionKey::cancel);
        g.closeIfUnused();
        throw e;
      }
      g.answerKeys.put(receiver, keys);
      g.receivers.add(receiver);
      g.selector.wakeup();
      return g;
    }
  }

  /**
   * Stops delivering to {@code receiver}; the last receiver to leave closes the socket and ends the
   * thread. The answer channels stay open (their owner closes them). A delivery to
   * {@code receiver} in progress may still finish; see {@link Receiver#close()}.
   */
  void leave(Receiver receiver) {
    synchronized (OPEN) {
      receivers.remove(receiver);
      List<SelectionKey> keys = answerKeys.remove(receiver);
      if (keys != null) {
        keys.forEach(SelectionKey::cancel);
      }
      selector.wakeup(); // a cancelled key lets go of its channel at the next select
      closeIfUnused();
    }
  }

  // Caller holds OPEN.
  private void closeIfUnused() {
    if (receivers.isEmpty() && !closed) {
      closed = true;
      OPEN.remove(key, this);
      selector.wakeup();
      Sockets.closeQuietly(group);
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
            SelectionKey k = ready.next();
            ready.remove();
            DatagramChannel ch = (DatagramChannel) k.channel();
            Receiver only = (Receiver) k.attachment(); // null: the group's, for every receiver
            InetSocketAddress from;
            while (!closed && k.isValid()
                && (from = (InetSocketAddress) ch.receive(buf.clear())) != null) {
              deliver(only, buf, from);
            }
          }
          if (failures >= PERSISTENT_FAILURES) {
            LOG.log(Level.INFO, "Discovery receives again on {0}", thread.getName());
          }
          failures = 0;
        } catch (ClosedSelectorException e) {
          break;
        } catch (ClosedChannelException e) {
          if (!group.isOpen()) {
            break; // closed by the last leave
          }
          // An answer channel closed by its owner between select and receive: its key goes.
        } catch (IOException | RuntimeException e) {
          failures++;
          if (failures == PERSISTENT_FAILURES) {
            LOG.log(Level.ERROR, "Discovery has failed to receive " + failures
                + " times in a row; it keeps trying, once a second at most", e);
          } else if (failures < PERSISTENT_FAILURES) {
            LOG.log(Level.WARNING, "Discovery could not receive; retrying", e);
          }
          pause(Math.min(MAX_PAUSE_NANOS,
              TimeUnit.MILLISECONDS.toNanos(1) << Math.min(failures, 20)));
        }
      }
    } catch (IOException e) {
      // Closing the selector at the end: nothing is left to release.
    } finally {
      synchronized (OPEN) {
        OPEN.remove(key, this);
        closed = true;
      }
      Sockets.closeQuietly(group);
    }
  }

  /** Waits {@code nanos}, or less if the last receiver leaves meanwhile. */
  private void pause(long nanos) {
    long until = System.nanoTime() + nanos;
    for (long left = nanos; left > 0 && !closed; left = until - System.nanoTime()) {
      LockSupport.parkNanos(this, Math.min(left, TimeUnit.MILLISECONDS.toNanos(50)));
    }
  }

  /**
   * Hands a datagram to its receivers, which handle it on their own threads: this thread only
   * reads (see {@link Receiver} for why). One copy of the packet is shared by all of them.
   */
  private void deliver(Receiver only, ByteBuffer buf, InetSocketAddress from) {
    byte[] packet = Arrays.copyOf(buf.array(), buf.position());
    if (only != null) {
      deliver(only, packet, from, null);
      return;
    }
    Receiver.Decoded decoded = new Receiver.Decoded(); // shared by receivers of the same system
    for (Receiver r : receivers) {
      deliver(r, packet, from, decoded);
    }
  }

  /** Hands a datagram to one receiver; its failure is its own, not the others' nor the socket's. */
  private static void deliver(Receiver r, byte[] packet, InetSocketAddress from,
      Receiver.Decoded decoded) {
    try {
      r.offer(packet, from, decoded);
    } catch (RuntimeException e) {
      LOG.log(Level.WARNING, "A discovery receiver failed on a datagram from " + from
          + "; delivery goes on", e);
    }
  }
}
