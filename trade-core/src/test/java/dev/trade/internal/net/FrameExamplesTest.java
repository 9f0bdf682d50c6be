package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEService;
import dev.trade.internal.admin.Proofs;
import dev.trade.internal.call.Arguments;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Heartbeat;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.Digest;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import org.junit.jupiter.api.Test;

/**
 * Keeps the worked examples of {@code docs/protocol.md} true: each hex block marked
 * {@code <!-- example: name -->} must be exactly what the real classes produce for the inputs the
 * document states. Text after {@code #} on a line of a block is commentary. The path is relative
 * to the trade-core module directory, where Surefire runs.
 */
class FrameExamplesTest {
  private static final Path DOC = Path.of("..", "docs", "protocol.md");
  private static final Pattern EXAMPLE =
      Pattern.compile("<!-- example: ([a-z-]+) -->\\s*```text\\n(.*?)```", Pattern.DOTALL);

  // The inputs the document states.
  static final UUID ARM = UUID.fromString("00112233-4455-6677-8899-aabbccddeeff");
  static final UUID HUB = UUID.fromString("ffeeddcc-bbaa-9988-7766-554433221100");
  static final byte[] ARM_NONCE = sequence(0x00);
  static final byte[] HUB_NONCE = sequence(0x20);

  public static class RobotArm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  private static byte[] sequence(int first) {
    byte[] b = new byte[32];
    for (int i = 0; i < b.length; i++) {
      b[i] = (byte) (first + i);
    }
    return b;
  }

  private static Handshake armHandshake() {
    return new Handshake(new Handshake.Identity("diarc", ARM, "arm", "robot1", List.of()), "diarcUser");
  }

  private static byte[] handshakeFrame(int type, byte[] payload) throws IOException {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    Handshake.writeFrame(new DataOutputStream(bytes), type, payload);
    return bytes.toByteArray();
  }

  private static Codec codec() {
    return new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  }

  /** The arm provides openGripper(int); the hub calls it with 3. */
  private static byte[] callFrame() throws Exception {
    Registry registry = new Registry(ARM.toString(), "arm", "robot1");
    List<LocalService> services = registry.register(new RobotArm(), List.of());
    ServiceDescriptor d = services.get(0).descriptor();
    assertEquals("openGripper(int)", d.signature());
    RemoteCalls hub = new RemoteCalls(HUB, codec(), null, null, null, 1 << 26);
    return hub.callFrame(ARM, 1, d.serviceId(), 30_000, Arguments.normalize(d, new Object[] {3}));
  }

  /** The same call with a context of one entry. */
  private static byte[] callFrameWithContext() throws Exception {
    Registry registry = new Registry(ARM.toString(), "arm", "robot1");
    ServiceDescriptor d = registry.register(new RobotArm(), List.of()).get(0).descriptor();
    RemoteCalls hub = new RemoteCalls(HUB, codec(), null, null, null, 1 << 26);
    return hub.callFrame(ARM, 1, d.serviceId(), 30_000, Arguments.normalize(d, new Object[] {3}),
        CallContext.of(Map.of("x.trace", "42")));
  }

  /** The same call under a lock: its id and the service's fencing token (docs/locks.md). */
  private static byte[] callFrameUnderLock() throws Exception {
    Registry registry = new Registry(ARM.toString(), "arm", "robot1");
    ServiceDescriptor d = registry.register(new RobotArm(), List.of()).get(0).descriptor();
    RemoteCalls hub = new RemoteCalls(HUB, codec(), null, null, null, 1 << 26);
    return hub.callFrame(ARM, 1, d.serviceId(), 30_000, Arguments.normalize(d, new Object[] {3}),
        CallContext.of(Map.of("trade.lock", "0f1e2d3c-4b5a-6978-8796-a5b4c3d2e1f0",
            "trade.lock.token", "7")));
  }

  /** The arm's refusal of a call to a service another lock holds: status 7 and a text. */
  private static byte[] lockedReplyFrame() throws Exception {
    byte[] call = callFrame();
    byte[] payload = Arrays.copyOfRange(call, Wire.HEADER, call.length);
    ByteSink out = new RemoteCalls(ARM, codec(), null, null, null, 1 << 26)
        .replyStart(payload, Wire.FAILED_LOCKED);
    out.writeText("locked");
    return Frames.finish(out);
  }

  /**
   * The same call made inside a hook whose wrapper is the hub's service 1: the reserved context
   * key {@code trade.hooks} (docs/hooks.md) names the hooks running on the call's path.
   */
  private static byte[] callFrameInsideHook() throws Exception {
    Registry registry = new Registry(ARM.toString(), "arm", "robot1");
    ServiceDescriptor d = registry.register(new RobotArm(), List.of()).get(0).descriptor();
    RemoteCalls hub = new RemoteCalls(HUB, codec(), null, null, null, 1 << 26);
    return hub.callFrame(ARM, 1, d.serviceId(), 30_000, Arguments.normalize(d, new Object[] {3}),
        CallContext.of(Map.of("trade.hooks", HUB + "/1")));
  }

  /** The arm's successful reply to that call: {@code true}. */
  private static byte[] replyFrame() throws Exception {
    byte[] call = callFrame();
    byte[] payload = Arrays.copyOfRange(call, Wire.HEADER, call.length);
    RemoteCalls arm = new RemoteCalls(ARM, codec(), null, null, null, 1 << 26);
    ByteSink out = arm.replyStart(payload, Wire.OK);
    codec().write(Boolean.TRUE, out);
    return Frames.finish(out);
  }

  private static Map<String, byte[]> documented() throws IOException {
    String doc = Files.readString(DOC, StandardCharsets.UTF_8);
    Map<String, byte[]> examples = new LinkedHashMap<>();
    Matcher m = EXAMPLE.matcher(doc);
    while (m.find()) {
      StringBuilder hex = new StringBuilder();
      for (String line : m.group(2).split("\n")) {
        int comment = line.indexOf('#');
        hex.append((comment < 0 ? line : line.substring(0, comment)).replaceAll("\\s", ""));
      }
      examples.put(m.group(1), HexFormat.of().parseHex(hex));
    }
    return examples;
  }

  private static void assertDocumented(String name, byte[] actual) throws IOException {
    byte[] documented = documented().get(name);
    String hex = HexFormat.ofDelimiter(" ").formatHex(actual);
    assertTrue(documented != null, "no example '" + name + "' in " + DOC + "; it is\n" + hex);
    assertEquals(hex, HexFormat.ofDelimiter(" ").formatHex(documented), "example '" + name + "'");
  }

  @Test
  void helloExample() throws Exception {
    assertDocumented("hello", handshakeFrame(Wire.HELLO, armHandshake().hello(ARM_NONCE, 0)));
  }

  @Test
  void authExample() throws Exception {
    assertDocumented("auth-key", Handshake.deriveKey("diarc", "diarcUser"));
    byte[] proof = armHandshake().mac(Handshake.OPENED, ARM_NONCE, HUB_NONCE, ARM, HUB);
    assertDocumented("auth", handshakeFrame(Wire.AUTH, proof));
  }

  /** The recipe the document gives, computed independently of {@link Handshake}. */
  @Test
  void authRecipeOfTheDocumentIsWhatTheCodeComputes() throws Exception {
    MessageDigest sha = MessageDigest.getInstance("SHA-256");
    byte[] key = sha.digest("TRADE-credentials-v1\0diarc\0diarcUser".getBytes(StandardCharsets.UTF_8));
    Mac mac = Mac.getInstance("HmacSHA256");
    mac.init(new SecretKeySpec(key, "HmacSHA256"));
    mac.update("TRADE-auth-v2".getBytes(StandardCharsets.US_ASCII));
    mac.update("diarc".getBytes(StandardCharsets.UTF_8));
    mac.update((byte) 'I'); // the arm opened the connection
    mac.update(ByteBuffer.allocate(32).putLong(ARM.getMostSignificantBits())
        .putLong(ARM.getLeastSignificantBits()).putLong(HUB.getMostSignificantBits())
        .putLong(HUB.getLeastSignificantBits()).array());
    mac.update(ARM_NONCE);
    mac.update(HUB_NONCE);
    assertArrayEquals(mac.doFinal(),
        armHandshake().mac(Handshake.OPENED, ARM_NONCE, HUB_NONCE, ARM, HUB));
  }

  @Test
  void callExample() throws Exception {
    assertDocumented("call", callFrame());
  }

  @Test
  void callWithContextExample() throws Exception {
    assertDocumented("call-context", callFrameWithContext());
  }

  /** The call of {@link #callFrame()} with alice's proof (docs/protocol.md, "Proof of a principal"). */
  private static byte[] callFrameWithProof() throws Exception {
    Registry registry = new Registry(ARM.toString(), "arm", "robot1");
    ServiceDescriptor d = registry.register(new RobotArm(), List.of()).get(0).descriptor();
    RemoteCalls hub = new RemoteCalls(HUB, codec(), null, null, null, 1 << 26);
    String proof = Proofs.sign("alice", Proofs.key("alice", "alice-secret-1"), HUB.toString(),
        ARM.toString(), d.serviceId(), 1_700_000_000_000L, "000102030405060708090a0b0c0d0e0f");
    return hub.callFrame(ARM, 1, d.serviceId(), 30_000, Arguments.normalize(d, new Object[] {3}),
        CallContext.of(Map.of(Proofs.KEY, proof)));
  }

  @Test
  void callWithProofExample() throws Exception {
    assertDocumented("auth-proof-key", Proofs.key("alice", "alice-secret-1"));
    assertDocumented("call-auth", callFrameWithProof());
  }

  /** The proof recipe of the document, computed with the JDK's Mac. */
  @Test
  void proofRecipeOfTheDocumentIsWhatTheCodeComputes() throws Exception {
    Mac mac = Mac.getInstance("HmacSHA256");
    mac.init(new SecretKeySpec("alice-secret-1".getBytes(StandardCharsets.UTF_8), "HmacSHA256"));
    byte[] key = mac.doFinal("trade.auth.key.1\nalice".getBytes(StandardCharsets.UTF_8));
    mac.init(new SecretKeySpec(key, "HmacSHA256"));
    String nonce = "000102030405060708090a0b0c0d0e0f";
    byte[] expected = mac.doFinal(("trade.auth.1\nalice\n" + HUB + "\n" + ARM + "\n1\n"
        + "1700000000000\n" + nonce).getBytes(StandardCharsets.UTF_8));
    assertEquals("1 alice 1700000000000 " + nonce + " " + HexFormat.of().formatHex(expected),
        Proofs.sign("alice", Proofs.key("alice", "alice-secret-1"), HUB.toString(),
            ARM.toString(), 1, 1_700_000_000_000L, nonce));
  }

  @Test
  void callUnderLockExample() throws Exception {
    assertDocumented("call-lock", callFrameUnderLock());
  }

  @Test
  void lockedReplyExample() throws Exception {
    assertDocumented("reply-locked", lockedReplyFrame());
  }

  @Test
  void callInsideHookExample() throws Exception {
    assertDocumented("call-hooks", callFrameInsideHook());
  }

  @Test
  void replyExample() throws Exception {
    assertDocumented("reply", replyFrame());
  }

  @Test
  void tableRequestExample() throws Exception {
    assertDocumented("table-request", StateFrames.tableRequest(ARM.toString()));
  }

  @Test
  void digestExample() throws Exception {
    assertDocumented("digest", Digest.frame(
        List.of(new Topology.LinkState(ARM.toString(), 1, Set.of(HUB.toString()))),
        new Table(ARM.toString(), 1, List.of()), List.of()));
  }

  @Test
  void pingExample() throws Exception {
    assertDocumented("ping", Frames.finish(Frames.start(Wire.PING, 0)));
  }

  @Test
  void probeAndEchoExamples() throws Exception {
    assertDocumented("ping-probe", Heartbeat.ping(Heartbeat.PROBE, 0x00000a1b2c3d4e5fL));
    assertDocumented("ping-echo", Heartbeat.ping(Heartbeat.ECHO, 0x00000a1b2c3d4e5fL));
  }
}
