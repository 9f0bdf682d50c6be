package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.net.link.Connector;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Bytes that are not the protocol, sent to a listening container: each time that one connection
 * is closed with a logged reason, and a well-behaved container linked to the same server keeps
 * calling its service throughout.
 */
@Timeout(120)
class HostileInputTest {
  /** A bound for what is refused at once, generous for a busy machine (log lines say why). */
  private static final Duration PROMPTLY = Duration.ofSeconds(20);
  private static final int HANDSHAKE_TIMEOUT_MS = 1_000;
  private static final int MAX_FRAME = 65_536;

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  private final LogCapture log = new LogCapture();
  private final TRADEContainer server = Hubs.hubBuilder("victim")
      .property("TIMEOUT_CLIENT_SOCKET", String.valueOf(HANDSHAKE_TIMEOUT_MS))
      .property("MAXFRAMESIZE", String.valueOf(MAX_FRAME)).build();
  private final TRADEContainer client = Hubs.spokeBuilder("bystander", server).build();
  private final InetSocketAddress address = new InetSocketAddress("127.0.0.1",
      Integer.parseInt(server.getServerAddresses().get(0).split("@")[1]));
  private SteadyCaller caller;

  @BeforeEach
  void linkTheBystander() throws TRADEException {
    server.registerAllServices(new Arm());
    TRADEServiceConstraints open = new TRADEServiceConstraints().name("openGripper");
    Await.until(Duration.ofSeconds(10), () -> !client.getAvailableServices(open).isEmpty(),
        "openGripper to reach the bystander");
    TRADEServiceInfo service = client.getAvailableService(open);
    caller = new SteadyCaller(service, 3);
    caller.awaitMore(5);
  }

  @AfterEach
  void bystanderWasNeverHurt() throws InterruptedException {
    try {
      caller.awaitMore(20);
      caller.close();
      caller.assertNoFailures();
    } finally {
      client.close();
      server.close();
      log.close();
    }
  }

  private RawPeer connect() throws IOException {
    return RawPeer.connect(address);
  }

  /** Sends {@code bytes} on a fresh connection and expects it closed promptly. */
  private void expectClosed(byte[] bytes) throws IOException {
    try (RawPeer p = connect()) {
      p.send(bytes);
      p.awaitClosed(PROMPTLY);
    }
  }

  /** Authenticates, sends {@code bytes}, and expects that link closed promptly. */
  private void expectLinkClosed(byte[] bytes) throws Exception {
    try (RawPeer p = connect()) {
      p.handshake("intruder");
      p.send(bytes);
      p.awaitClosed(PROMPTLY);
    }
  }

  private void awaitLog(String... parts) {
    Await.until(Duration.ofSeconds(5), () -> log.has(Level.WARNING, parts) || log.has(Level.INFO, parts),
        "a log line with " + Arrays.toString(parts) + "; last lines:\n" + log.tail());
  }

  @Test
  void randomBytesBeforeTheHandshake() throws IOException {
    Random random = new Random(42);
    for (int i = 0; i < 50; i++) {
      byte[] noise = new byte[1 + random.nextInt(2048)];
      random.nextBytes(noise);
      expectClosed(noise);
    }
    awaitLog("refused connection from");
  }

  @Test
  void truncatedHelloIsDroppedWhenTheHandshakeTimesOut() throws Exception {
    byte[] hello = helloFrame();
    try (RawPeer p = connect()) {
      p.send(Arrays.copyOf(hello, hello.length / 2)); // and then nothing
      Duration took = p.awaitClosed(Duration.ofMillis(HANDSHAKE_TIMEOUT_MS + 20_000));
      assertTrue(took.toMillis() >= HANDSHAKE_TIMEOUT_MS - 100, "closed after " + took);
    }
    awaitLog("refused connection from", "handshake not finished within TIMEOUT_CLIENT_SOCKET="
        + HANDSHAKE_TIMEOUT_MS + " ms");

    try (RawPeer p = connect()) { // the same, but the peer hangs up
      p.send(Arrays.copyOf(hello, hello.length / 2));
      p.socket.shutdownOutput();
      p.awaitClosed(PROMPTLY);
    }
    awaitLog("refused connection from", "peer closed the connection during the handshake");
  }

  @Test
  void helloSentByteByByteIsDroppedAtTheHandshakeDeadline() throws Exception {
    byte[] hello = helloFrame();
    try (RawPeer p = connect()) {
      long start = System.nanoTime();
      // Each byte comes well within the read timeout; the whole would take 25 s.
      for (int i = 0; i < hello.length && !p.isClosedNow(); i++) {
        p.send(new byte[] {hello[i]});
        LockSupport.parkNanos(300_000_000); // the attacker's pace
      }
      long tookMs = (System.nanoTime() - start) / 1_000_000;
      // Without the handshake's deadline it would stay open for the 25 s the bytes take.
      assertTrue(tookMs < HANDSHAKE_TIMEOUT_MS + 12_000, "still open after " + tookMs + " ms");
    }
    awaitLog("refused connection from", "handshake not finished within TIMEOUT_CLIENT_SOCKET="
        + HANDSHAKE_TIMEOUT_MS + " ms");
  }

  @Test
  void helloWithLengthFieldsBeyondItsFrameIsRefusedAsMalformed() throws IOException {
    // The system id claims 255 bytes; the frame ends after 12.
    ByteBuffer b = ByteBuffer.allocate(4 + 1 + 1 + 12);
    b.put("TRDE".getBytes(StandardCharsets.US_ASCII)).put((byte) 1).put((byte) 255).put(new byte[12]);
    expectRefusal(b.array(), Wire.REFUSE_MALFORMED, "malformed HELLO");

    // 200 addresses, more than the 16 a HELLO may carry.
    ByteBuffer many = ByteBuffer.allocate(4 + 1 + 6 + 16 + 2 + 1);
    many.put("TRDE".getBytes(StandardCharsets.US_ASCII)).put((byte) 1)
        .put((byte) 5).put("diarc".getBytes(StandardCharsets.US_ASCII))
        .putLong(1).putLong(2).put((byte) 0).put((byte) 0).put((byte) 200);
    expectRefusal(many.array(), Wire.REFUSE_MALFORMED, "too many addresses: 200");
    awaitLog("refused connection from", "too many addresses: 200");
  }

  /** Sends a HELLO payload; expects the server's HELLO, then REFUSE with this reason, then EOF. */
  private void expectRefusal(byte[] helloPayload, int reason, String text) throws IOException {
    try (RawPeer p = connect()) {
      p.send(RawPeer.frame(Wire.HELLO, helloPayload));
      assertEquals(Wire.HELLO, p.readFrame()[0]);
      byte[] refuse = p.readFrame();
      assertEquals(Wire.REFUSE, refuse[0]);
      ByteBuffer r = ByteBuffer.wrap(refuse, 1, refuse.length - 1);
      assertEquals(reason, r.get());
      int length = r.getShort() & 0xffff;
      assertEquals(length, r.remaining());
      String message = new String(refuse, 4, length, StandardCharsets.UTF_8);
      assertTrue(message.contains(text), message);
      p.awaitClosed(PROMPTLY);
    }
  }

  @Test
  void handshakeFramesOverTheirLimitAndClaimsOfTwoGigabytes() throws IOException {
    for (int length : new int[] {Wire.MAX_HANDSHAKE_FRAME + 1, Integer.MAX_VALUE, 0x8000_0000, 1, 0}) {
      expectClosed(RawPeer.frame(length, Wire.VERSION, Wire.HELLO, new byte[16]));
      awaitLog("bad handshake frame length " + length);
    }
  }

  @Test
  void authenticatedFramesOverMaxFrameSizeAndClaimsOfTwoGigabytes() throws Exception {
    for (int length : new int[] {MAX_FRAME + 1, Integer.MAX_VALUE, 0x8000_0000, 1}) {
      expectLinkClosed(RawPeer.frame(length, Wire.VERSION, Wire.PING, new byte[16]));
      awaitLog("malformed frame from intruder: length " + length + " (limit MAXFRAMESIZE=" + MAX_FRAME + ")");
    }
  }

  @Test
  void aFrameOfExactlyMaxFrameSizeIsRead() throws Exception {
    try (RawPeer p = connect()) {
      p.handshake("intruder");
      p.send(RawPeer.frame(Wire.PING, new byte[MAX_FRAME - 2])); // PING ignores its payload
      p.send(RawPeer.frame(99, new byte[0])); // then something that closes the link, with a reason
      p.awaitClosed(PROMPTLY);
    }
    awaitLog("unknown frame type 99");
  }

  @Test
  void garbageAfterTheHandshake() throws Exception {
    expectLinkClosed(RawPeer.frame(99, new byte[3]));
    awaitLog("unknown frame type 99");
    expectLinkClosed(RawPeer.frame(Wire.HELLO, new byte[3]));
    awaitLog("unknown frame type 1");
    expectLinkClosed(RawPeer.frame(6, 2, Wire.PING, new byte[4]));
    awaitLog("frame of protocol version 2 from intruder");
    expectLinkClosed(RawPeer.frame(Wire.CALL, new byte[10]));
    awaitLog("CALL of 10 bytes, shorter than its fixed fields (54)");
    // One to pass on, long enough for its ids but not its timeout: was an index out of bounds.
    byte[] shortCall = new byte[Frames.MIN_CALL - 1];
    java.nio.ByteBuffer.wrap(shortCall).putLong(16, 7).putLong(24, 9); // to a container elsewhere
    shortCall[32] = 5;
    expectLinkClosed(RawPeer.frame(Wire.CALL, shortCall));
    awaitLog("CALL of 53 bytes, shorter than its fixed fields (54)");
    // A replication frame is read on the control thread; the reason must still reach the log.
    expectLinkClosed(RawPeer.frame(Wire.LINKS, new byte[] {(byte) 0xff, (byte) 0xff, (byte) 0xff}));
    awaitLog("link to intruder closed: malformed replication frame");
    Random random = new Random(7);
    for (int i = 0; i < 20; i++) {
      byte[] noise = new byte[1 + random.nextInt(4096)];
      random.nextBytes(noise);
      expectLinkClosed(noise);
    }
  }

  @Test
  void twoHundredGarbageConnectionsDoNotGrowThreadsWithoutBound() throws Exception {
    int baseline = tradeThreads();
    AtomicInteger peak = new AtomicInteger(baseline);
    Thread sampler = new Thread(() -> {
      while (!Thread.currentThread().isInterrupted()) {
        peak.accumulateAndGet(tradeThreads(), Math::max);
        LockSupport.parkNanos(2_000_000); // the sampling period
      }
    });
    sampler.start();
    List<RawPeer> peers = new ArrayList<>();
    Random random = new Random(200);
    try {
      for (int i = 0; i < 200; i++) {
        RawPeer p = connect();
        peers.add(p);
        if (i % 2 == 0) { // half send a plausible header and then stall, half send noise
          p.send(RawPeer.frame(Wire.MAX_HANDSHAKE_FRAME, Wire.VERSION, Wire.HELLO, new byte[8]));
        } else {
          byte[] noise = new byte[64];
          random.nextBytes(noise);
          p.send(noise);
        }
      }
      for (RawPeer p : peers) {
        p.awaitClosed(Duration.ofMillis(HANDSHAKE_TIMEOUT_MS + 5_000));
      }
    } finally {
      sampler.interrupt();
      sampler.join();
      for (RawPeer p : peers) {
        p.close();
      }
    }
    assertTrue(peak.get() <= baseline + Connector.MAX_HANDSHAKES + 4,
        "peak of " + peak + " trade threads, baseline " + baseline);
    Await.until(Duration.ofSeconds(10), () -> tradeThreads() <= baseline + 2,
        "trade threads back near " + baseline + " (now " + tradeThreads() + ")");
  }

  @Test
  void connectionsBeyondTheHandshakeLimitAreClosedAtOnce() throws Exception {
    try (TRADEContainer slow = Hubs.hubBuilder("slowgate")
        .property("TIMEOUT_CLIENT_SOCKET", "20000").build()) {
      String[] a = slow.getServerAddresses().get(0).split("@");
      InetSocketAddress gate = new InetSocketAddress(a[0], Integer.parseInt(a[1]));
      List<RawPeer> stalled = new ArrayList<>();
      try {
        for (int i = 0; i < Connector.MAX_HANDSHAKES; i++) {
          RawPeer p = RawPeer.connect(gate);
          stalled.add(p);
          p.send(new byte[] {0, 0, 0, 100}); // a HELLO is coming... slowly
        }
        Await.until(Duration.ofSeconds(10),
            () -> threadsNamed("trade-handshake-slowgate-") == Connector.MAX_HANDSHAKES,
            Connector.MAX_HANDSHAKES + " handshakes in progress");
        try (RawPeer extra = RawPeer.connect(gate)) {
          extra.awaitClosed(Duration.ofSeconds(5)); // not the 20 s of a handshake
        }
        awaitLog("refused connection from", Connector.MAX_HANDSHAKES + " handshakes in progress already");
        assertEquals(Connector.MAX_HANDSHAKES, threadsNamed("trade-handshake-slowgate-"));
      } finally {
        for (RawPeer p : stalled) {
          p.close();
        }
      }
    }
  }

  private static int tradeThreads() {
    return threadsNamed("trade-");
  }

  private static int threadsNamed(String prefix) {
    int n = 0;
    for (Thread t : Thread.getAllStackTraces().keySet()) {
      if (t.isAlive() && t.getName().startsWith(prefix)) {
        n++;
      }
    }
    return n;
  }

  private static byte[] helloFrame() throws IOException {
    Handshake h = new Handshake(new Handshake.Identity("diarc", UUID.randomUUID(), "half", "localhost",
        List.of()), "diarcUser");
    byte[] frame = RawPeer.frame(Wire.HELLO, h.hello(new byte[32], 0));
    assertArrayEquals(new byte[] {'T', 'R', 'D', 'E'}, Arrays.copyOfRange(frame, 6, 10));
    return frame;
  }
}
