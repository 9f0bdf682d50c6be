package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.LoopbackLinks;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Registry;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.Arrays;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Which neighbours a container passes a link state on to: not the one it came from, not the
 * owner's neighbours (the owner sent it to them), and not those that sent the same version here
 * too, as most do while the control thread runs behind the links' readers; and which versions it
 * skips (those a newer one queued behind outdates).
 */
class FloodForwardingTest {
  private final UUID self = UUID.randomUUID();
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
  private final Map<UUID, Link> links = new ConcurrentHashMap<>();
  /** Tasks the replication scheduled on the control thread: route computations above all. */
  private final AtomicInteger scheduled = new AtomicInteger();
  private final LoopbackLinks loopback = new LoopbackLinks();
  private final Replication replication = new Replication(self, new Registry(self.toString(), "x", "host"),
      codec, links, 60_000_000_000L, (task, delay) -> scheduled.incrementAndGet(), container -> { });

  @AfterEach
  void close() throws IOException {
    loopback.close();
    timer.shutdownNow();
  }

  /** A link to a neighbour named {@code name}; returns what the neighbour reads. */
  private InputStream link(String name, Link[] made) throws IOException {
    InputStream[] far = new InputStream[1];
    made[0] = loopback.link(UUID.randomUUID(), name, far);
    links.put(made[0].peerId, made[0]);
    return far[0];
  }

  /** Reads the next frame a neighbour got and asserts that it is {@code frame}. */
  private static void assertSent(byte[] frame, InputStream at, String what) throws IOException {
    DataInputStream in = new DataInputStream(at);
    assertEquals(frame.length - 4, in.readInt(), what);
    byte[] got = new byte[frame.length - 4];
    in.readFully(got);
    assertTrue(Arrays.equals(frame, 4, frame.length, got, 0, got.length), what);
  }

  @Test
  void aLinkStateGoesOnlyToNeighboursThatHaveNotSentIt() throws Exception {
    Link[] a = new Link[1];
    Link[] b = new Link[1];
    Link[] c = new Link[1];
    InputStream atA = link("a", a);
    InputStream atB = link("b", b);
    InputStream atC = link("c", c);
    byte[] frame = StateFrames.links(new Topology.LinkState(UUID.randomUUID().toString(), 1,
        Set.of(UUID.randomUUID().toString())));
    byte[] state = Arrays.copyOfRange(frame, Wire.HEADER, frame.length);
    // The readers of a and b: a's copy queues for the control thread, b's is dropped as a copy.
    assertFalse(replication.isStale(a[0], Wire.LINKS, frame, Wire.HEADER, state.length));
    assertTrue(replication.isStale(b[0], Wire.LINKS, frame, Wire.HEADER, state.length));
    // The control thread applies a's copy and passes it on; on loopback, what is written is at
    // the far end when the write returns.
    replication.received(a[0], Wire.LINKS, state);
    replication.flushQueued();
    assertSent(frame, atC, "c had no copy and gets one");
    assertEquals(0, atB.available(), "b sent this version itself");
    assertEquals(0, atA.available(), "it came from a");
  }

  @Test
  void aVersionThatANewerOneQueuedBehindSupersedesIsSkipped() throws Exception {
    Link[] a = new Link[1];
    Link[] b = new Link[1];
    Link[] c = new Link[1];
    link("a", a);
    link("b", b);
    InputStream atC = link("c", c);
    String owner = UUID.randomUUID().toString();
    String x = UUID.randomUUID().toString();
    String y = UUID.randomUUID().toString();
    byte[] first = StateFrames.links(new Topology.LinkState(owner, 1, Set.of(x)));
    byte[] second = StateFrames.links(new Topology.LinkState(owner, 2, Set.of(x, y)));
    byte[] one = Arrays.copyOfRange(first, Wire.HEADER, first.length);
    byte[] two = Arrays.copyOfRange(second, Wire.HEADER, second.length);
    // Both versions queue for the control thread (a busy one), one after the other.
    assertFalse(replication.isStale(a[0], Wire.LINKS, first, Wire.HEADER, one.length));
    assertFalse(replication.isStale(b[0], Wire.LINKS, second, Wire.HEADER, two.length));
    int before = scheduled.get();
    replication.received(a[0], Wire.LINKS, one);
    replication.flushQueued();
    assertEquals(0, atC.available(), "version 1 is outdated by version 2, queued behind it");
    assertEquals(before, scheduled.get(), "nor applied: no route computation for it");
    replication.received(b[0], Wire.LINKS, two);
    replication.flushQueued();
    assertSent(second, atC, "c gets version 2");
    assertEquals(0, atC.available(), "and nothing else");
    assertEquals(before + 1, scheduled.get(), "version 2 is applied, and routes follow");
  }
}
