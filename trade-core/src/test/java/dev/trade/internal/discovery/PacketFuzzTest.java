package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.KEY;
import static dev.trade.internal.discovery.Fixtures.SYSTEM;
import static dev.trade.internal.discovery.Fixtures.address;

import dev.trade.internal.discovery.BadPacketException.Reason;
import dev.trade.testing.Findings;
import dev.trade.testing.Mutator;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Structured fuzzing of discovery packets (docs/reliability.md). Three inputs in four have their
 * body mutated and are signed again with the system's key, so that the parser behind the HMAC is
 * reached; the others are mutated whole, signature included. Each decodes or is refused with a
 * {@link BadPacketException}; nothing else escapes. Its share of {@code -Dtrade.fuzz.inputs} runs
 * with seed {@code -Dtrade.fuzz.seed}.
 */
@Timeout(3_600)
class PacketFuzzTest {
  static final double SHARE = 0.3;

  /** Unsigned bodies of valid announcements of several shapes. */
  private static List<byte[]> bodies() {
    List<InetSocketAddress> many = new ArrayList<>();
    for (int i = 0; i < Packets.MAX_ADDRESSES; i++) {
      many.add(address(i % 2 == 0 ? "10.0.0." + i : "fd00::" + i, 10_000 + i));
    }
    List<Announcement> announcements = List.of(
        new Announcement(1, SYSTEM, "c1", "arm", List.of(), 1, 1_700_000_000_000L),
        new Announcement(1, SYSTEM, "00112233-4455-6677-8899-aabbccddeeff", "gripper ☃",
            List.of(address("127.0.0.1", 10002), address("::1", 10003)), 7, 1_700_000_000_001L),
        new Announcement(1, SYSTEM, "c".repeat(Packets.MAX_CONTAINER_ID), "n".repeat(200), many,
            Long.MAX_VALUE, 1_700_000_000_002L));
    List<byte[]> bodies = new ArrayList<>();
    for (Announcement a : announcements) {
      byte[] packet = Packets.encode(a, KEY);
      bodies.add(Arrays.copyOf(packet, packet.length - Packets.MAC_LENGTH));
    }
    return bodies;
  }

  @Test
  void mutatedPacketsDecodeOrAreRefusedTyped() {
    Mutator mutator = new Mutator(Mutator.seed(), bodies());
    Signer signer = new Signer(KEY);
    int inputs = Mutator.inputs(SHARE);
    long decoded = 0;
    Map<Reason, Long> refused = new EnumMap<>(Reason.class);
    try (Findings findings = new Findings("discovery packets")) {
      for (int i = 0; i < inputs; i++) {
        byte[] body = mutator.next();
        byte[] input = mutator.random().nextInt(4) == 0
            ? mutator.mutate(Fixtures.sign(mutator.sample(), KEY))
            : Fixtures.sign(body, KEY);
        try {
          Packets.decode(input, input.length, SYSTEM, signer);
          decoded++;
        } catch (BadPacketException e) {
          refused.merge(e.reason(), 1L, Long::sum);
        } catch (RuntimeException | Error e) {
          findings.add(input, e);
        }
      }
      findings.report("inputs=" + inputs + " decoded=" + decoded + " refused=" + refused);
      findings.assertNone();
    }
  }
}
