package dev.trade.internal.discovery;

import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.LongAdder;
import java.util.function.Supplier;

/**
 * The announcing half of {@link Discovery}: sends an announcement per interface to the group in a
 * burst at start, then every interval and on request; and one straight to a newcomer, in answer
 * to its first announcement. It sends on a scheduler thread: the container's timer when discovery
 * is given one (one thread fewer to start per container), else a daemon thread of its own.
 *
 * <p>What it logs while the start burst goes out waits until the burst has been sent (or the
 * announcer closes): the first log record of a JVM sets up its logging and date formatting, tens of
 * milliseconds of CPU that would otherwise compete with the container's first link-ups.
 *
 * <p>Every send happens under {@code lock}, and so do the switches: once {@link #setOn(boolean)
 * setOn(false)} or {@link #close()} has returned, nothing more is sent. Thread-safe.
 */
final class Announcer {
  /** Delays of the start burst: a new container is heard within a few ms even if one is lost. */
  static final long[] BURST_MILLIS = {0, 20, 50, 100, 200};
  private static final Logger LOG = System.getLogger(Discovery.class.getName());

  private final String systemId;
  private final String containerId;
  private final String containerName;
  private final Signer signer; // the scheduler thread's, guarded by lock like every send
  private final InetSocketAddress target;
  private final Supplier<List<InetSocketAddress>> addresses;
  private final List<NetworkInterface> interfaces;
  private final List<DatagramChannel> channels;
  private final ScheduledExecutorService scheduler;
  private final boolean ownScheduler;
  private volatile ScheduledFuture<?> steady;
  private final AtomicLong sequence = new AtomicLong();
  private final LongAdder sent = new LongAdder();
  /** Newcomers with an answer pending, by the address their announcement came from. */
  private final Set<InetSocketAddress> answering = ConcurrentHashMap.newKeySet();
  private final Object lock = new Object();
  // Guarded by lock: the last state logged per interface, so that only changes are logged.
  private final Map<String, String> states = new HashMap<>();
  // Guarded by lock: what each interface announces, as last worked out; see plan(int).
  private final Plan[] plans;
  // Guarded by lock: log lines held back until the start burst has been sent; null after that.
  private List<Runnable> heldLines = new ArrayList<>();
  private volatile boolean on; // Written under lock.
  private boolean closed; // Guarded by lock.

  /**
   * @param channels one per interface, in the same order; closed by {@link #close()}
   * @param scheduler where to send; null for a thread of its own, named {@code threadName}. A
   *     given one is not shut down by {@link #close()}, only this announcer's tasks end.
   */
  Announcer(String systemId, String containerId, String containerName, byte[] key,
      InetSocketAddress target, Supplier<List<InetSocketAddress>> addresses,
      List<NetworkInterface> interfaces, List<DatagramChannel> channels, boolean on,
      ScheduledExecutorService scheduler, String threadName) {
    this.systemId = systemId;
    this.containerId = containerId;
    this.containerName = containerName;
    this.signer = new Signer(key);
    this.target = target;
    this.addresses = addresses;
    this.interfaces = List.copyOf(interfaces);
    this.channels = List.copyOf(channels);
    this.plans = new Plan[this.interfaces.size()];
    this.on = on;
    this.ownScheduler = scheduler == null;
    this.scheduler = scheduler != null ? scheduler : Executors.newSingleThreadScheduledExecutor(r -> {
      Thread t = new Thread(r, threadName);
      t.setDaemon(true);
      return t;
    });
  }

  /**
   * Starts the start burst and the steady announcements.
   *
   * @param startLine logs what this discovery does; written with the lines held back at start,
   *     before them
   */
  void start(Duration interval, Runnable startLine) {
    synchronized (lock) {
      heldLines.add(startLine);
    }
    scheduleBurst();
    long ms = interval.toMillis();
    try {
      // After the burst's last announcement, which is due at the same time and was queued first.
      scheduler.schedule(this::writeHeldLines, BURST_MILLIS[BURST_MILLIS.length - 1],
          TimeUnit.MILLISECONDS);
      steady = scheduler.scheduleWithFixedDelay(this::announceToGroup, ms, ms, TimeUnit.MILLISECONDS);
    } catch (RejectedExecutionException e) {
      // A given scheduler shut down: its container is closing.
      writeHeldLines();
    }
  }

  /** Turning it on sends a burst, as at start. */
  void setOn(boolean on) {
    synchronized (lock) {
      boolean was = this.on;
      this.on = on;
      if (on && !was && !closed) {
        scheduleBurst();
      }
    }
  }

  boolean isOn() {
    return on;
  }

  /** Announces now, with the listen addresses as they are now. */
  void announceNow() {
    synchronized (lock) {
      Arrays.fill(plans, null);
    }
    try {
      scheduler.execute(this::announceToGroup);
    } catch (RejectedExecutionException e) {
      // Closed: nothing to announce.
    }
  }

  /**
   * Announces soon to {@code newcomer} alone, in answer to its first announcement: without it, a
   * newcomer would learn about this container only at its next steady announcement, seconds away.
   * The answer goes to the socket the newcomer sent from, not to the group: the others know this
   * container already, and with n containers a multicast answer to each of n joins would cost
   * n³ packets received. It goes out on the interface whose network holds the newcomer's address
   * and lists that interface's addresses; a newcomer on none of them hears the next steady
   * announcement instead.
   */
  void answer(InetSocketAddress newcomer) {
    if (answering.add(newcomer)) {
      try {
        scheduler.execute(() -> {
          answering.remove(newcomer);
          for (int i = 0; i < channels.size(); i++) {
            if (Interfaces.reaches(interfaces.get(i), newcomer.getAddress())) {
              announce(i, newcomer);
              return;
            }
          }
        });
      } catch (RejectedExecutionException e) {
        // Closed: nothing to announce.
      }
    }
  }

  /** The scheduler it sends on (given, or its own): the receiver handles datagrams there too. */
  Executor executor() {
    return scheduler;
  }

  long sentCount() {
    return sent.sum();
  }

  /**
   * Stops announcing (and its own scheduler) and closes the channels; waits for a send in progress.
   * Idempotent.
   */
  void close() {
    synchronized (lock) {
      closed = true;
    }
    writeHeldLines(); // a container closed within its start burst still says what it did
    // Tasks still queued on a given scheduler find it closed and send nothing.
    if (ownScheduler) {
      scheduler.shutdownNow();
    } else if (steady != null) {
      steady.cancel(false);
    }
    channels.forEach(Sockets::closeQuietly);
  }

  private void scheduleBurst() {
    try {
      for (long delay : BURST_MILLIS) {
        scheduler.schedule(this::announceToGroup, delay, TimeUnit.MILLISECONDS);
      }
    } catch (RejectedExecutionException e) {
      // Closed meanwhile.
    }
  }

  /** One packet per interface to the group. Never throws: a periodic task that throws is cancelled. */
  private void announceToGroup() {
    for (int i = 0; i < channels.size(); i++) {
      announce(i, target);
    }
  }

  /** One packet on the {@code i}th interface to {@code to}. Never throws. */
  private void announce(int i, InetSocketAddress to) {
    synchronized (lock) {
      if (!on || closed) {
        return;
      }
      Plan plan = plan(i);
      if (plan == null) {
        return;
      }
      NetworkInterface nif = plan.nif;
      List<InetSocketAddress> listen = plan.listen;
      List<InetSocketAddress> mine = plan.mine;
      if (mine.isEmpty()) {
        note(nif, Level.INFO, "nothing to announce: " + (listen.isEmpty()
            ? "no listen addresses" : "none of the listen addresses " + Announcement.format(listen) + " is on it"));
        return;
      }
      try {
        // The text is checked and encoded once per plan (at most once a second), not per packet:
        // while a system of 100 starts, a container answers a newcomer every few milliseconds.
        if (plan.template == null) {
          plan.template = new Packets.Template(new Announcement(Packets.VERSION, systemId,
              containerId, containerName, mine, 1, 0));
        }
        byte[] packet = plan.template.packet(sequence.incrementAndGet(), System.currentTimeMillis(),
            signer);
        // Non-blocking (the receiver reads answers from this channel): 0 means no room just now,
        // and the packet is lost, as a datagram may be anyway.
        if (channels.get(i).send(ByteBuffer.wrap(packet), to) == 0) {
          throw new IOException("the socket's send buffer is full");
        }
        sent.increment();
        if (!plan.noted) {
          note(nif, Level.INFO, "announcing " + Announcement.format(mine) + " as '" + containerName + "'");
          plan.noted = true;
        }
      } catch (IOException | RuntimeException e) {
        plan.noted = false; // the next success is news
        note(nif, Level.WARNING, "cannot send: " + e);
      }
    }
  }

  /**
   * What the {@code i}th interface announces: the interface, the listen addresses, those on it.
   * Its mutable fields are guarded by lock.
   */
  private static final class Plan {
    final NetworkInterface nif;
    final List<InetSocketAddress> listen;
    final List<InetSocketAddress> mine;
    final long at;
    /** The announcement of {@link #mine} but for sequence, time and HMAC; made at the first send. */
    Packets.Template template;
    /** Whether a successful send with this plan has been noted (logged if news). */
    boolean noted;

    Plan(NetworkInterface nif, List<InetSocketAddress> listen, List<InetSocketAddress> mine,
        long at) {
      this.nif = nif;
      this.listen = listen;
      this.mine = mine;
      this.at = at;
    }
  }

  /**
   * What the {@code i}th interface announces, worked out again at most once a second and after
   * {@link #announceNow()}: listing the listen addresses (wildcards expanded) and looking the
   * interface up take system calls, and while a large system starts a container answers a
   * newcomer every few milliseconds. A changed address (DHCP) is still announced within a second.
   * Caller holds lock.
   *
   * @return null if the listen addresses could not be had (logged)
   */
  private Plan plan(int i) {
    long now = System.nanoTime();
    Plan plan = plans[i];
    if (plan == null || now - plan.at >= 1_000_000_000L) {
      List<InetSocketAddress> listen;
      try {
        listen = List.copyOf(addresses.get());
      } catch (RuntimeException e) {
        LOG.log(Level.WARNING, "Discovery could not get the listen addresses to announce", e);
        return null;
      }
      NetworkInterface nif = Interfaces.refresh(interfaces.get(i));
      plan = new Plan(nif, listen, Interfaces.announceable(nif, listen), now);
      plans[i] = plan;
    }
    return plan;
  }

  // Caller holds lock.
  private void note(NetworkInterface nif, Level level, String state) {
    if (!state.equals(states.put(nif.getName(), state))) {
      Runnable line = () -> LOG.log(level, "Discovery on {0} to {1}: {2}", nif.getName(),
          Announcement.format(target), state);
      if (heldLines != null) {
        heldLines.add(line); // in order with the rest, warnings too
      } else {
        line.run();
      }
    }
  }

  /** Writes the lines held back at start, once; outside the lock, which every send takes. */
  private void writeHeldLines() {
    List<Runnable> lines;
    synchronized (lock) {
      lines = heldLines;
      heldLines = null;
    }
    if (lines != null) {
      lines.forEach(Runnable::run);
    }
  }
}
