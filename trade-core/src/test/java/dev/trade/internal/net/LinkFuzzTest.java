package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.call.Arguments;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.testing.Await;
import dev.trade.testing.Findings;
import dev.trade.testing.Mutator;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Structured fuzzing of a live container over real links (docs/reliability.md): the frames of a
 * real session between two containers are recorded by a {@link Tap}, mutated, and sent to a victim
 * container, before authentication (HELLO, and AUTH after a valid HELLO) and after it (every frame
 * kind, with the recorded container's id replaced by the fuzzing peer's own). After each frame that
 * leaves the stream whole, a probe call on the same link must be answered, or the link closed. A
 * bystander container calls the victim throughout and every one of its calls must succeed. No
 * exception may be uncaught on any thread, nothing may be logged as an error or with an Error, no
 * unchecked exception may be caught by a safety net, and heap and threads must come back to their
 * level before.
 */
@Timeout(3_600)
class LinkFuzzTest {
  static final double FRAME_SHARE = 0.2;
  static final double HANDSHAKE_SHARE = 0.1;
  private static final int MAX_FRAME = 65_536;
  private static final Duration GENEROUS = Duration.ofSeconds(30);
  /** Unchecked exceptions named in a log line: a check that is missing somewhere. */
  private static final Pattern UNCHECKED =
      Pattern.compile("java\\.(lang|nio|util)\\.[A-Za-z.]*(Exception|Error)");

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  public static class Hand {
    @TRADEService
    public String closeGripper(String how) {
      return how + " closed";
    }
  }

  private final TRADEContainer victim = TRADEContainer.builder().name("victim")
      .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0")
      .property("TIMEOUT_CLIENT_SOCKET", "2000")
      .property("MAXFRAMESIZE", String.valueOf(MAX_FRAME)).build();
  private final InetSocketAddress address = new InetSocketAddress("127.0.0.1",
      Integer.parseInt(victim.getServerAddresses().get(0).split("@")[1]));
  private final List<AutoCloseable> closing = new ArrayList<>();
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  private long probes;

  @AfterEach
  void close() throws Exception {
    for (int i = closing.size() - 1; i >= 0; i--) {
      closing.get(i).close();
    }
    victim.close();
  }

  /** The frames of a session that links, lists, calls both ways, pings and says goodbye. */
  private List<byte[]> record(UUID[] modelId) throws Exception {
    Tap tap = new Tap(address);
    closing.add(tap);
    TRADEContainer model = TRADEContainer.builder().name("model").property("HEARTBEATINTERVAL", "100")
        .property("CONNECTCONTAINERS", tap.address()).build();
    modelId[0] = UUID.fromString(model.getId());
    try {
      TRADEServiceConstraints open = new TRADEServiceConstraints().name("openGripper");
      Await.until(GENEROUS, () -> !model.getAvailableServices(open).isEmpty(), "openGripper at the model");
      model.getAvailableService(open).call(Boolean.class, 3);
      model.registerAllServices(new Hand()); // a DELTA
      TRADEServiceConstraints close = new TRADEServiceConstraints().name("closeGripper");
      Await.until(GENEROUS, () -> !victim.getAvailableServices(close).isEmpty(), "closeGripper at the victim");
      victim.getAvailableService(close).call(String.class, "gently");
      Await.until(GENEROUS, () -> tap.saw(Wire.PING), "a PING");
    } finally {
      model.close();
    }
    Await.until(GENEROUS, () -> tap.saw(Wire.GOODBYE), "a GOODBYE");
    List<byte[]> frames = new ArrayList<>(tap.fromDialler());
    frames.addAll(tap.fromTarget());
    // Kinds a two-container session does not always show: crafted as the model would send them.
    frames.add(StateFrames.tableRequest(model.getId()));
    frames.add(new RemoteCalls(modelId[0], codec, null, null, null, MAX_FRAME).callFrame(
        UUID.fromString(victim.getId()), 1, RawPeer.firstUserServiceId(victim), 30_000,
        Arguments.normalize(armDescriptor(), new Object[] {3}), CallContext.of(Map.of("x.trace", "42"))));
    return frames;
  }

  private ServiceDescriptor armDescriptor() throws Exception {
    return new Registry(victim.getId(), "victim", "localhost").register(new Arm(), List.of()).get(0)
        .descriptor();
  }

  @Test
  void mutatedHandshakesAndFramesNeverHurtTheContainerOrItsCallers() throws Exception {
    victim.registerAllServices(new Arm());
    UUID[] modelId = new UUID[1];
    List<byte[]> frames = record(modelId);
    List<byte[]> handshake = frames.stream().filter(f -> f[5] <= Wire.REFUSE).toList();
    List<byte[]> linked = frames.stream().filter(f -> f[5] > Wire.REFUSE).toList();
    for (int type : new int[] {Wire.HELLO, Wire.AUTH, Wire.PING, Wire.GOODBYE, Wire.LINKS, Wire.TABLE,
        Wire.DELTA, Wire.TABLE_REQUEST, Wire.CALL, Wire.REPLY}) {
      assertTrue(frames.stream().anyMatch(f -> f[5] == type), "no sample of frame type " + type);
    }

    TRADEContainer bystander = TRADEContainer.builder().name("bystander")
        .property("CONNECTCONTAINERS", victim.getServerAddresses().get(0)).build();
    closing.add(bystander::close);
    TRADEServiceConstraints open = new TRADEServiceConstraints().name("openGripper");
    Await.until(GENEROUS, () -> !bystander.getAvailableServices(open).isEmpty(), "openGripper at the bystander");
    SteadyCaller caller = new SteadyCaller(bystander.getAvailableService(open), 3);
    closing.add(caller);
    caller.awaitMore(5);

    Logger logger = Logger.getLogger("dev.trade");
    Level level = logger.getLevel();
    try (Findings findings = new Findings("links")) {
      Handler watch = watch(findings);
      logger.setLevel(Level.INFO);
      logger.setUseParentHandlers(false);
      logger.addHandler(watch);
      try {
        long heapBefore = usedHeapAfterGc();
        int threadsBefore = threads();
        long served = caller.successes();
        Mutator mutator = new Mutator(Mutator.seed(), handshake);
        long start = System.nanoTime();
        int handshakes = fuzzHandshakes(mutator, findings, caller);
        double handshakeSeconds = (System.nanoTime() - start) / 1e9;
        mutator = new Mutator(Mutator.seed(), linked);
        start = System.nanoTime();
        String frameFigures = fuzzFrames(mutator, modelId[0], findings, caller);
        double frameSeconds = (System.nanoTime() - start) / 1e9;
        caller.awaitMore(20);
        try {
          // Links' threads end as their peers' sockets close, which takes a while on a busy
          // machine after hundreds of thousands of them.
          Await.until(Duration.ofSeconds(120), () -> threads() <= threadsBefore + 2,
              "the threads to come back to " + threadsBefore + " (+2)");
        } catch (AssertionError e) {
          throw new AssertionError(e.getMessage() + "; threads now: " + Thread.getAllStackTraces()
              .keySet().stream().map(Thread::getName).sorted().toList(), e);
        }
        long heapAfterRun = usedHeapAfterGc();
        // The victim keeps the state of each container that left for a minute (Replication's
        // grace): tens of thousands of fuzzing peers then weigh some MB, which must go.
        Await.until(Duration.ofSeconds(180), () -> usedHeapAfterGc() < heapBefore + (8 << 20),
            "the heap to come back within 8 MB of " + (heapBefore >> 10) + " KiB");
        long heapAfter = usedHeapAfterGc();
        findings.report(String.format("handshake inputs=%d in %.0f s; frame inputs=%s in %.0f s;"
            + " bystander calls=%d, failed=0; heap %d -> %d KiB right after, %d KiB settled; threads %d -> %d",
            handshakes, handshakeSeconds, frameFigures, frameSeconds, caller.successes() - served,
            heapBefore >> 10, heapAfterRun >> 10, heapAfter >> 10, threadsBefore,
            threads()));
        findings.assertNone();
        caller.assertNoFailures();
      } finally {
        logger.removeHandler(watch);
        logger.setUseParentHandlers(true);
        logger.setLevel(level);
      }
    }
  }

  /** A log handler that makes a finding of errors, Errors and unchecked exceptions caught. */
  private static Handler watch(Findings findings) {
    return new Handler() {
      @Override
      public void publish(LogRecord r) {
        String message = String.valueOf(r.getMessage());
        Throwable thrown = r.getThrown();
        if (r.getLevel().intValue() >= Level.SEVERE.intValue() || thrown instanceof Error
            || thrown instanceof RuntimeException || UNCHECKED.matcher(message).find()) {
          findings.add("logged " + r.getLevel() + ": " + message,
              thrown != null ? thrown : new AssertionError(message));
        }
      }

      @Override
      public void flush() {}

      @Override
      public void close() {}
    };
  }

  /**
   * Before authentication: two inputs in three are a mutated first frame; the others follow a
   * valid HELLO, in the place of the AUTH that ends the handshake. Each on a fresh connection,
   * which must then be closed.
   */
  private int fuzzHandshakes(Mutator mutator, Findings findings, SteadyCaller caller) throws IOException {
    int inputs = Mutator.inputs(HANDSHAKE_SHARE);
    for (int i = 0; i < inputs; i++) {
      byte[] input = mutator.next();
      try (RawPeer p = RawPeer.connect(address)) {
        if (mutator.random().nextInt(3) == 0) {
          p.begin("fuzzer", 1); // a valid HELLO; the input stands where our AUTH would
        }
        p.send(fitLength(mutator, input));
        p.socket.shutdownOutput();
        p.awaitClosed(GENEROUS);
      } catch (AssertionError e) {
        findings.add(input, e);
      }
      if (i % 2_000 == 1_999) {
        caller.awaitMore(1);
      }
    }
    return inputs;
  }

  /**
   * After authentication: each mutated frame on an authenticated link of a peer with a fresh id.
   * When the bytes sent end with a whole frame, a probe call on the same link must be answered or
   * the link closed; when they end inside a frame, the peer hangs up (the victim would wait for the
   * rest).
   */
  private String fuzzFrames(Mutator mutator, UUID modelId, Findings findings, SteadyCaller caller)
      throws Exception {
    int inputs = Mutator.inputs(FRAME_SHARE);
    long answered = 0;
    long closed = 0;
    long cut = 0;
    RawPeer peer = null;
    RemoteCalls calls = null;
    Object[] args = Arguments.normalize(armDescriptor(), new Object[] {3});
    long serviceId = RawPeer.firstUserServiceId(victim);
    UUID victimId = UUID.fromString(victim.getId());
    for (int i = 0; i < inputs; i++) {
      if (peer == null) {
        UUID id = new UUID(mutator.random().nextLong(), mutator.random().nextLong());
        peer = RawPeer.connect(victim, id);
        peer.handshake("fuzzer-" + i);
        calls = new RemoteCalls(id, codec, null, null, null, MAX_FRAME);
      }
      byte[] input = replace(fitLength(mutator, mutator.next()), modelId, peer.id);
      peer.send(input);
      if (!endsWithWholeFrame(input)) {
        cut++;
        peer.close();
        peer = null;
      } else {
        long request = ++probes;
        peer.send(calls.callFrame(victimId, request, serviceId, 30_000, args));
        try {
          if (awaitReply(peer, request)) {
            answered++;
          } else {
            closed++;
            peer.close();
            peer = null;
          }
        } catch (SocketTimeoutException e) {
          findings.add(input, new AssertionError("no answer to a probe call on an open link within "
              + GENEROUS.toSeconds() + " s", e));
          peer.close();
          peer = null;
        }
      }
      if (i % 2_000 == 1_999) {
        caller.awaitMore(1);
      }
    }
    if (peer != null) {
      peer.close();
    }
    return inputs + " (probe answered=" + answered + ", link closed=" + closed + ", ended inside a frame="
        + cut + ")";
  }

  /** Reads until the REPLY to {@code request} (true) or the end of the connection (false). */
  private static boolean awaitReply(RawPeer peer, long request) throws IOException {
    long deadline = System.nanoTime() + GENEROUS.toNanos();
    while (true) {
      byte[] f;
      try {
        f = peer.readFrame();
      } catch (SocketTimeoutException e) {
        if (System.nanoTime() - deadline > 0) {
          throw e;
        }
        continue;
      } catch (SocketException | java.io.EOFException e) {
        return false;
      }
      if (f[0] == Wire.REPLY && Frames.requestId(Arrays.copyOfRange(f, 1, f.length)) == request) {
        return true;
      }
    }
  }

  /** Three inputs in four get a length field that fits them, so that the mutation reaches the payload. */
  private static byte[] fitLength(Mutator mutator, byte[] input) {
    if (input.length >= Wire.HEADER && mutator.random().nextInt(4) != 0) {
      ByteBuffer.wrap(input).putInt(0, input.length - 4);
    }
    return input;
  }

  /** Whether {@code bytes} end where a frame ends, as the receiver's framing reads them. */
  static boolean endsWithWholeFrame(byte[] bytes) {
    int at = 0;
    while (at < bytes.length) {
      if (bytes.length - at < 4) {
        return false;
      }
      long length = ByteBuffer.wrap(bytes, at, 4).getInt() & 0xffff_ffffL;
      if (length < 2 || length > MAX_FRAME) {
        return true; // refused at once: the link closes
      }
      if (at + 4 + length > bytes.length) {
        return false;
      }
      at += 4 + (int) length;
    }
    return true;
  }

  /** {@code bytes} with {@code from}'s id, binary and as text, replaced by {@code to}'s. */
  static byte[] replace(byte[] bytes, UUID from, UUID to) {
    byte[] b = replace(bytes, binary(from), binary(to));
    return replace(b, from.toString().getBytes(StandardCharsets.UTF_8),
        to.toString().getBytes(StandardCharsets.UTF_8));
  }

  private static byte[] binary(UUID id) {
    return ByteBuffer.allocate(16).putLong(id.getMostSignificantBits())
        .putLong(id.getLeastSignificantBits()).array();
  }

  private static byte[] replace(byte[] bytes, byte[] from, byte[] to) {
    for (int i = 0; i + from.length <= bytes.length; i++) {
      if (Arrays.equals(bytes, i, i + from.length, from, 0, from.length)) {
        System.arraycopy(to, 0, bytes, i, to.length);
        i += from.length - 1;
      }
    }
    return bytes;
  }

  private static int threads() {
    return Thread.getAllStackTraces().size();
  }

  private static long usedHeapAfterGc() {
    Runtime r = Runtime.getRuntime();
    System.gc();
    return r.totalMemory() - r.freeMemory();
  }
}
