package dev.trade.internal.net.link;

import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.time.Scheduler;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Keeps links alive and finds silent peers: every {@code HEARTBEATINTERVAL} each link that sent
 * nothing for half that long sends a PING (so an idle link carries one per interval), and a link
 * that received nothing for {@code FAILURETIMEOUT} is closed. A closed or reset socket is noticed
 * at once by the link's reader; this catches the silent cases (a frozen process, a pulled cable).
 * A link whose write has waited for {@code FAILURETIMEOUT} is closed too: its peer does not read
 * (stuck, or hostile while it goes on pinging), and every thread that sends over the link, callers
 * and the control thread among them, would otherwise wait for it for good; closing the socket ends
 * the write with an exception.
 *
 * <p>Silence is judged only while this container itself runs on time: a beat that comes more than
 * half an interval late means this process was stalled (a long GC pause, a suspended VM, an
 * overloaded host), and the frames its peers sent meanwhile still wait unread in the socket
 * buffers. Every link then gets a full {@code FAILURETIMEOUT} from the end of the stall, so that
 * a pause here never closes the links of healthy peers. Thread-safe: beats run on the timer.
 *
 * <p>Every PING the heartbeat sends is also a round-trip probe ({@link RoundTrip}): it carries a
 * token the peer echoes at once, in a PING of its own. A link so busy that it needs no PING for
 * {@link #PROBE_EVERY} intervals gets one anyway, so that its round-trip time stays current.
 */
public final class Heartbeat {
  /** A busy link gets a probe after this many intervals without one. */
  static final int PROBE_EVERY = 10;
  /** The first byte of a PING payload that asks for an echo, and of the echo. */
  public static final int PROBE = 1;
  public static final int ECHO = 2;
  /** A probe's or an echo's payload: the kind, then the u64 token. */
  static final int PROBE_PAYLOAD = 1 + 8;

  private final Collection<Link> links;
  private final long interval;
  private final long silence;
  private final long probeEvery;
  private final Scheduler scheduler;
  private final ScheduledExecutorService timer;
  private final ExecutorService workers;
  private volatile ScheduledFuture<?> beating;
  // Timer thread only.
  private long lastBeat;
  /** When the last stall of this process ended (nanoTime); silence counts from there at most. */
  private volatile long resumed;

  /** @param links the live links, read at every beat */
  public Heartbeat(Collection<Link> links, Duration interval, Duration silence,
      Scheduler scheduler, ExecutorService workers) {
    this.links = links;
    this.interval = interval.toNanos();
    this.silence = silence.toNanos();
    this.probeEvery = PROBE_EVERY * this.interval;
    this.scheduler = scheduler;
    this.timer = scheduler.timer();
    this.workers = workers;
  }

  /**
   * Pings a link that just came up, at once: its peer counts silence from the handshake on, while
   * this side's first beat for it may be one and a half intervals away and its first other frames
   * wait for the control thread. Without it, a new link had the least slack of all against a
   * stall of this process. It is the link's first round-trip probe too. Called on the thread that
   * made the link; never blocks on a new link.
   */
  public void greet(Link l) {
    try {
      probe(l);
    } catch (IOException e) {
      // send() closed the link; its reader reports it.
    }
  }

  /** Sends {@code l} a PING that is a round-trip probe, timed at the moment it leaves. */
  private void probe(Link l) throws IOException {
    l.send(ping(PROBE, l.roundTrip.sent(scheduler.nanoTime())));
  }

  /** A PING frame whose payload is {@code kind} ({@link #PROBE} or {@link #ECHO}) and a token. */
  public static byte[] ping(int kind, long token) {
    ByteSink sink = Frames.start(Wire.PING, PROBE_PAYLOAD);
    sink.writeByte(kind);
    sink.writeLong(token);
    return Frames.finish(sink);
  }

  /** A PING arrived on {@code l} (on its reading thread): see {@link #pinged(Link, byte[], long)}. */
  public void pinged(Link l, byte[] payload) {
    pinged(l, payload, scheduler.nanoTime());
  }

  /**
   * A PING with {@code payload} arrived on {@code l} at {@code now}: a probe is echoed at once, an
   * echo is timed; any other payload is ignored, as docs/protocol.md asks (an empty one is the
   * plain heartbeat of a peer that does not measure).
   */
  void pinged(Link l, byte[] payload, long now) {
    if (payload.length != PROBE_PAYLOAD) {
      return;
    }
    long token = ByteBuffer.wrap(payload, 1, 8).getLong();
    if (payload[0] == PROBE) {
      try {
        l.send(ping(ECHO, token));
      } catch (IOException e) {
        // The link is closing; its reading reports why.
      }
    } else if (payload[0] == ECHO) {
      l.roundTrip.echoed(token, now);
    }
  }

  /** Beats every interval on the scheduler's timer, at its clock's time, until {@link #stop}. */
  public void start() {
    started(scheduler.nanoTime());
    beating = timer.scheduleAtFixedRate(() -> beat(scheduler.nanoTime()), interval, interval,
        TimeUnit.NANOSECONDS);
  }

  /** Stops beating (the timer is the container's and goes on). */
  public void stop() {
    ScheduledFuture<?> b = beating;
    if (b != null) {
      b.cancel(false);
    }
  }

  /**
   * Counts beats from {@code now} (nanoTime), without scheduling any: {@link #start} does both;
   * tests that pass their own times to {@link #beat} call this alone.
   */
  void started(long now) {
    lastBeat = now;
    resumed = now;
  }

  /** One beat at {@code now} (nanoTime); package-private for tests, which pass their own times. */
  void beat(long now) {
    if (now - lastBeat > interval + interval / 2) {
      resumed = now;
    }
    lastBeat = now;
    List<Link> idle = null;
    for (Link l : links) {
      long writing = l.output.writingSince();
      if (writing != 0 && now - Math.max(writing, resumed) >= silence) {
        l.close("not reading: a write has waited " + TimeUnit.NANOSECONDS.toMillis(now - writing)
            + " ms (FAILURETIMEOUT=" + TimeUnit.NANOSECONDS.toMillis(silence) + ")");
        continue;
      }
      long quiet = now - Math.max(l.lastReceived, resumed);
      if (quiet >= silence) {
        closeSilent(l, now - l.lastReceived);
        continue;
      }
      if (silence - quiet < interval) {
        // It would pass FAILURETIMEOUT before the next beat: look again exactly then, so that a
        // silent peer is declared gone after FAILURETIMEOUT, not up to one interval later.
        timer.schedule(() -> checkSilence(l), silence - quiet, TimeUnit.NANOSECONDS);
      }
      if ((now - l.lastSent >= interval / 2 || l.roundTrip.due(now, probeEvery)) && !l.pinging) {
        if (idle == null) {
          idle = new ArrayList<>();
        }
        l.pinging = true; // here, not on the worker: a ping still queued is not sent twice
        idle.add(l);
      }
    }
    if (idle != null) {
      ping(idle);
    }
  }

  /**
   * Pings on one worker, not on the timer: a ping that finds a peer's socket buffer full blocks
   * until the peer reads or the link closes, and the timer must go on beating for every other
   * link. A link whose ping still blocks is skipped by later beats, which ping the others on
   * another worker. One task per beat, not one per link: hundreds of links would otherwise start
   * as many threads.
   */
  private void ping(List<Link> idle) {
    try {
      workers.execute(() -> {
        for (Link l : idle) {
          try {
            probe(l);
          } catch (IOException e) {
            // The link is closing; its reading reports why.
          } finally {
            l.pinging = false;
          }
        }
      });
    } catch (RejectedExecutionException e) {
      // The container is closing.
    }
  }

  private void checkSilence(Link l) {
    long now = scheduler.nanoTime();
    if (!l.isClosed() && now - Math.max(l.lastReceived, resumed) >= silence) {
      closeSilent(l, now - l.lastReceived);
    }
  }

  private void closeSilent(Link l, long quietNanos) {
    l.close("silent for " + TimeUnit.NANOSECONDS.toMillis(quietNanos) + " ms (FAILURETIMEOUT="
        + TimeUnit.NANOSECONDS.toMillis(silence) + ")");
  }
}
