package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.time.Scheduler;
import java.io.DataInputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.AbstractExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The heartbeat on real links over loopback, with beats at times the test chooses: silence is
 * judged from the end of a stall of this process, idle links are pinged by one task per beat,
 * and a link whose ping is still under way is left out.
 */
@Timeout(30)
class HeartbeatTest {
  private static final long MS = 1_000_000L;
  private static final int LINKS = 20;
  private final List<Socket> sockets = new ArrayList<>();
  private final List<Link> links = new ArrayList<>();
  private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
  private final Tasks workers = new Tasks();
  private ServerSocket server;
  private Heartbeat heartbeat;
  /** When the heartbeat started counting (nanoTime); the tests' beats come after it. */
  private long started;

  /** Keeps the tasks it is given, to run them when the test says. */
  private static final class Tasks extends AbstractExecutorService {
    final List<Runnable> tasks = new ArrayList<>();

    @Override
    public synchronized void execute(Runnable r) {
      tasks.add(r);
    }

    synchronized void runAll() {
      tasks.forEach(Runnable::run);
      tasks.clear();
    }

    @Override
    public void shutdown() {}

    @Override
    public List<Runnable> shutdownNow() {
      return List.of();
    }

    @Override
    public boolean isShutdown() {
      return false;
    }

    @Override
    public boolean isTerminated() {
      return false;
    }

    @Override
    public boolean awaitTermination(long timeout, TimeUnit unit) {
      return true;
    }
  }

  @BeforeEach
  void connect() throws IOException {
    server = new ServerSocket(0, LINKS, InetAddress.getLoopbackAddress());
    for (int i = 0; i < LINKS; i++) {
      Socket near = new Socket();
      near.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), server.getLocalPort()));
      sockets.add(near);
      sockets.add(server.accept());
      links.add(new Link(near, new Handshake.Peer(UUID.randomUUID(), "p" + i, "host", List.of(),
          null), true, 1 << 20));
    }
    // Beats come from the test only, at the times it passes: none is scheduled.
    heartbeat = new Heartbeat(links, Duration.ofMillis(1000), Duration.ofMillis(3000), Scheduler.of(timer),
        workers);
    started = System.nanoTime();
    heartbeat.started(started);
  }

  @AfterEach
  void close() throws IOException {
    timer.shutdownNow();
    for (Socket s : sockets) {
      s.close();
    }
    server.close();
  }

  private void quietSince(long nanos) {
    for (Link l : links) {
      l.lastReceived = nanos;
      l.lastSent = nanos;
    }
  }

  @Test
  void aLateBeatMeansThisProcessStalledAndClosesNothing() {
    long t = started;
    quietSince(t);
    // The next beat was due at t + 1 s and comes at t + 4 s: the peers' frames wait unread.
    heartbeat.beat(t + 4_000 * MS);
    links.forEach(l -> assertFalse(l.isClosed(), "closed although this process was the one stalled"));
    // On time from then on: silent for FAILURETIMEOUT after the stall, they are closed.
    heartbeat.beat(t + 5_000 * MS);
    heartbeat.beat(t + 6_000 * MS);
    links.forEach(l -> assertFalse(l.isClosed(), "closed before FAILURETIMEOUT after the stall"));
    heartbeat.beat(t + 7_000 * MS);
    links.forEach(l -> assertTrue(l.isClosed(), "a link silent for FAILURETIMEOUT stayed open"));
  }

  @Test
  void beatsOnTimeCloseSilentLinks() {
    long t = started;
    quietSince(t);
    for (int k = 1; k <= 3; k++) {
      heartbeat.beat(t + k * 1_000 * MS);
    }
    links.forEach(l -> assertTrue(l.isClosed(), "a link silent for FAILURETIMEOUT stayed open"));
  }

  @Test
  void idleLinksArePingedByOneTaskPerBeat() throws IOException {
    long t = started;
    quietSince(t);
    Link busy = links.get(0);
    busy.lastSent = t + 900 * MS; // sent something 100 ms before the beat
    heartbeat.beat(t + 1_000 * MS);
    assertEquals(1, workers.tasks.size(), "tasks for one beat");
    workers.runAll();
    for (int i = 0; i < LINKS; i++) {
      boolean pinged = pingArrived(sockets.get(2 * i + 1));
      assertEquals(i != 0, pinged, "link " + i + " pinged");
    }
  }

  @Test
  void aLinkWhosePingIsStillUnderWayIsLeftOut() throws IOException {
    long t = started;
    quietSince(t);
    Link stuck = links.get(3);
    stuck.pinging = true; // as if its ping blocked on a full socket buffer
    heartbeat.beat(t + 1_000 * MS);
    workers.runAll();
    for (int i = 0; i < LINKS; i++) {
      assertEquals(i != 3, pingArrived(sockets.get(2 * i + 1)), "link " + i + " pinged");
    }
    assertTrue(stuck.pinging, "the flag belongs to the ping under way");
  }

  /**
   * A link that would pass FAILURETIMEOUT before the next beat is looked at exactly when it does,
   * so that a silent peer is declared gone after FAILURETIMEOUT, not up to an interval later.
   */
  @Test
  void aLinkThatGoesSilentForTooLongBeforeTheNextBeatIsLookedAtThen() {
    List<Long> delays = new ArrayList<>();
    ScheduledThreadPoolExecutor recording = new ScheduledThreadPoolExecutor(1) {
      @Override
      public ScheduledFuture<?> schedule(Runnable task, long delay, TimeUnit unit) {
        delays.add(unit.toMillis(delay));
        return super.schedule(task, 1, TimeUnit.DAYS); // never run: the test only reads the delay
      }
    };
    try {
      Heartbeat beats = new Heartbeat(links, Duration.ofMillis(1000), Duration.ofMillis(3000),
          Scheduler.of(recording), workers);
      beats.started(started);
      quietSince(started);
      beats.beat(started + 1_000 * MS);
      assertEquals(List.of(), delays, "silent for 1 s of 3: the next beats look");
      beats.beat(started + 2_000 * MS);
      assertEquals(List.of(), delays, "silent for 2 s of 3: the next beat comes at 3 s");
      beats.beat(started + 2_600 * MS);
      assertEquals(Collections.nCopies(LINKS, 400L), delays, "each looked at again at 3 s");
    } finally {
      recording.shutdownNow();
    }
  }

  /**
   * Every heartbeat PING is a probe the peer echoes at once; the echo of its token times the
   * link. A busy link, which needs no PING, gets a probe after PROBE_EVERY intervals anyway.
   */
  @Test
  void pingsAreProbesWhoseEchoesTimeTheLink() throws IOException {
    long t = started;
    quietSince(t);
    Link busy = links.get(0);
    busy.lastSent = t + 900 * MS;
    heartbeat.beat(t + 1_000 * MS);
    workers.runAll();
    Link idle = links.get(1);
    byte[] probe = pingPayload(sockets.get(3));
    assertEquals(Heartbeat.PROBE_PAYLOAD, probe.length, "a probe's payload");
    assertEquals(Heartbeat.PROBE, probe[0]);
    long token = ByteBuffer.wrap(probe, 1, 8).getLong();
    assertEquals(-1, idle.roundTripNanos(), "not echoed yet");
    heartbeat.pinged(idle, echo(token + 1), token + 300_000);
    assertEquals(-1, idle.roundTripNanos(), "an echo of another token counts for nothing");
    heartbeat.pinged(idle, echo(token), token + 300_000);
    assertEquals(300_000, idle.roundTripNanos());
    assertEquals(null, pingPayload(sockets.get(1)), "the busy link needs no PING yet");

    long later = t + Heartbeat.PROBE_EVERY * 1_000 * MS;
    for (Link l : links) {
      l.lastReceived = later - 100 * MS;
      l.lastSent = later - 100 * MS;
    }
    heartbeat.beat(later);
    workers.runAll();
    byte[] busyProbe = pingPayload(sockets.get(1));
    assertTrue(busyProbe != null && busyProbe[0] == Heartbeat.PROBE,
        "a busy link is probed every PROBE_EVERY intervals");
  }

  @Test
  void aProbeIsEchoedWithItsTokenAndOtherPayloadsAreIgnored() throws IOException {
    Link l = links.get(2);
    heartbeat.pinged(l, new byte[0], started);
    heartbeat.pinged(l, new byte[] {Heartbeat.PROBE, 1, 2}, started);
    byte[] probe = echo(0x0102030405060708L);
    probe[0] = Heartbeat.PROBE;
    heartbeat.pinged(l, probe, started);
    byte[] answer = pingPayload(sockets.get(5));
    assertEquals(Heartbeat.PROBE_PAYLOAD, answer.length, "only the probe is answered");
    assertEquals(Heartbeat.ECHO, answer[0]);
    assertEquals(0x0102030405060708L, ByteBuffer.wrap(answer, 1, 8).getLong());
    assertEquals(null, pingPayload(sockets.get(5)), "one answer");
  }

  private static byte[] echo(long token) {
    return ByteBuffer.allocate(Heartbeat.PROBE_PAYLOAD).put((byte) Heartbeat.ECHO).putLong(token)
        .array();
  }

  /** The payload of the PING frame waiting on {@code far}; null if none comes soon. */
  private static byte[] pingPayload(Socket far) throws IOException {
    far.setSoTimeout(200);
    try {
      DataInputStream in = new DataInputStream(far.getInputStream());
      int length = in.readInt();
      in.readUnsignedByte();
      assertEquals(Wire.PING, in.readUnsignedByte(), "frame type");
      return in.readNBytes(length - 2);
    } catch (java.net.SocketTimeoutException e) {
      return null;
    }
  }

  /** Whether a PING frame is waiting on {@code far}, without blocking for long. */
  private static boolean pingArrived(Socket far) throws IOException {
    far.setSoTimeout(200);
    try {
      DataInputStream in = new DataInputStream(far.getInputStream());
      int length = in.readInt(); // version, type, payload
      in.readUnsignedByte();
      int type = in.readUnsignedByte();
      in.skipNBytes(length - 2);
      return type == Wire.PING;
    } catch (java.net.SocketTimeoutException e) {
      return false;
    }
  }
}
