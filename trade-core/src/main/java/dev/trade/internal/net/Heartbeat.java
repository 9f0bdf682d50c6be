package dev.trade.internal.net;

import java.io.IOException;
import java.time.Duration;
import java.util.Collection;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Keeps links alive and finds silent peers: every {@code HEARTBEATINTERVAL} each link that sent
 * nothing for that long sends a PING, and a link that received nothing for {@code FAILURETIMEOUT}
 * is closed. A closed or reset socket is noticed at once by the link's reader; this catches the
 * silent cases (a frozen process, a pulled cable). Safe for concurrent use.
 */
final class Heartbeat {
  private static final byte[] PING = Frames.finish(Frames.start(Wire.PING, 0));

  private final Collection<Link> links;
  private final long interval;
  private final long silence;
  private final ScheduledExecutorService timer;
  private final ExecutorService workers;

  /** @param links the live links, read at every beat */
  Heartbeat(Collection<Link> links, Duration interval, Duration silence,
      ScheduledExecutorService timer, ExecutorService workers) {
    this.links = links;
    this.interval = interval.toNanos();
    this.silence = silence.toNanos();
    this.timer = timer;
    this.workers = workers;
  }

  void start() {
    timer.scheduleAtFixedRate(this::beat, interval, interval, TimeUnit.NANOSECONDS);
  }

  private void beat() {
    long now = System.nanoTime();
    for (Link l : links) {
      long quiet = now - l.lastReceived;
      if (quiet >= silence) {
        closeSilent(l, quiet);
        continue;
      }
      if (silence - quiet < interval) {
        // It would pass FAILURETIMEOUT before the next beat: look again exactly then, so that a
        // silent peer is declared gone after FAILURETIMEOUT, not up to one interval later.
        timer.schedule(() -> checkSilence(l), silence - quiet, TimeUnit.NANOSECONDS);
      }
      if (now - l.lastSent >= interval) {
        // On a worker: a ping that finds a large frame being written must not hold up the
        // heartbeats (and silence checks) of every other link.
        workers.execute(() -> {
          try {
            l.send(PING);
          } catch (IOException e) {
            // send() closed the link; its reader reports it.
          }
        });
      }
    }
  }

  private void checkSilence(Link l) {
    long quiet = System.nanoTime() - l.lastReceived;
    if (!l.isClosed() && quiet >= silence) {
      closeSilent(l, quiet);
    }
  }

  private void closeSilent(Link l, long quietNanos) {
    l.close("silent for " + TimeUnit.NANOSECONDS.toMillis(quietNanos) + " ms (FAILURETIMEOUT="
        + TimeUnit.NANOSECONDS.toMillis(silence) + ")");
  }
}
