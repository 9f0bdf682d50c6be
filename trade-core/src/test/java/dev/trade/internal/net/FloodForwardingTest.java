package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.registry.Registry;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Which neighbours a container passes a link state on to: not the one it came from, not the
 * owner's neighbours (the owner sent it to them), and not those that sent the same version here
 * too, as most do while the control thread runs behind the links' readers. And when its own state
 * goes out: soon after a link to a container it could not reach, a while after one that only
 * shortens paths.
 */
class FloodForwardingTest {
  private final UUID self = UUID.randomUUID();
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
  private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
  private final Map<UUID, Link> links = new ConcurrentHashMap<>();
  /** The tasks the replication scheduled, in order; they run when a test says. */
  private final List<Scheduled> scheduled = new ArrayList<>();

  private record Scheduled(Runnable task, long delayNanos) {}
  private final List<Socket> sockets = new ArrayList<>();
  private final List<Link> made = new ArrayList<>();
  private final Replication replication = new Replication(self, new Registry(self.toString(), "x", "host"),
      codec, links, new RemoteCalls(self, codec, container -> null, null, timer, 1 << 20),
      60_000_000_000L, (task, delay) -> scheduled.add(new Scheduled(task, delay)), container -> { });


  @AfterEach
  void close() throws IOException {
    made.forEach(l -> l.close("done"));
    for (Socket s : sockets) {
      s.close();
    }
    timer.shutdownNow();
  }

  /** A link to a neighbour named {@code name}; returns what the neighbour reads. */
  private InputStream link(String name, Link[] made) throws IOException {
    return link(UUID.randomUUID(), name, made);
  }

  private InputStream link(UUID id, String name, Link[] made) throws IOException {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      Socket near = new Socket();
      near.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), server.getLocalPort()));
      Socket far = server.accept();
      sockets.add(near);
      sockets.add(far);
      Handshake.Peer peer = new Handshake.Peer(id, name, "host", List.of(), null);
      Link link = new Link(near, peer, true, 1 << 20);
      links.put(peer.containerId(), link);
      made[0] = link;
      this.made.add(link);
      return far.getInputStream();
    }
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
    assertFalse(replication.isStale(a[0], Wire.LINKS, state));
    assertTrue(replication.isStale(b[0], Wire.LINKS, state));
    // The control thread applies a's copy and passes it on; on loopback, what is written is at
    // the far end when the write returns.
    replication.received(a[0], Wire.LINKS, state);
    replication.flushQueued();
    DataInputStream fromC = new DataInputStream(atC);
    assertEquals(frame.length - 4, fromC.readInt(), "c had no copy and gets one");
    byte[] got = new byte[frame.length - 4];
    fromC.readFully(got);
    assertEquals(Wire.LINKS, got[1]);
    assertEquals(0, atB.available(), "b sent this version itself");
    assertEquals(0, atA.available(), "it came from a");
  }

  @Test
  void aLinkThatOnlyShortensPathsGoesOutWithTheNextFloodAndAnUrgentOneAtOnce() throws Exception {
    Link[] a = new Link[1];
    DataInputStream atA = new DataInputStream(link("a", a));
    replication.linkUp(a[0]); // a could not be reached before: this container's state goes out
    replication.flushQueued();
    drain(atA);
    // a lists p, and p lists a: p can be reached through a.
    String p = UUID.randomUUID().toString();
    replication.received(a[0], Wire.LINKS, payload(a[0].peerKey, 1, self.toString(), p));
    replication.received(a[0], Wire.LINKS, payload(p, 1, a[0].peerKey));
    Link[] toP = new Link[1];
    InputStream atP = link(UUID.fromString(p), "p", toP);
    scheduled.clear();

    replication.linkUp(toP[0]);
    replication.flushQueued();
    assertEquals(0, atA.available(), "the new link only shortens paths: a is not told yet");
    assertEquals(1, scheduled.size());
    assertEquals(Replication.SHORTCUT_DELAY_NANOS, scheduled.get(0).delayNanos(), 100_000_000.0);
    assertTrue(atP.available() > 0, "p itself gets the state that lists it, with the others");

    // A link to a container that could not be reached before does not wait for it.
    Link[] q = new Link[1];
    link("q", q);
    replication.linkUp(q[0]);
    replication.flushQueued();
    List<String> listed = atA.available() > 0 ? ownState(atA) : null;
    if (listed == null) { // within the gap after the last flood: due at its end
      assertEquals(2, scheduled.size());
      assertTrue(scheduled.get(1).delayNanos() <= Replication.OWN_FLOOD_GAP_NANOS);
      scheduled.get(1).task().run();
      replication.flushQueued();
      listed = ownState(atA);
    }
    assertEquals(Set.of(a[0].peerKey, p, q[0].peerKey), Set.copyOf(listed), "with the shortcut");
    scheduled.get(0).task().run();
    replication.flushQueued();
    assertEquals(0, atA.available(), "the shortcut's own flood has nothing left to send");
  }

  private static byte[] payload(String owner, long version, String... neighbours) {
    byte[] frame = StateFrames.links(new Topology.LinkState(owner, version, Set.of(neighbours)));
    return Arrays.copyOfRange(frame, Wire.HEADER, frame.length);
  }

  /** Reads what is there now; on loopback, what was written is at the far end already. */
  private static void drain(DataInputStream in) throws IOException {
    in.skipNBytes(in.available());
  }

  /** Reads one frame, which must be this container's LINKS, and returns the neighbours it lists. */
  private List<String> ownState(DataInputStream in) throws Exception {
    byte[] frame = new byte[in.readInt()];
    in.readFully(frame);
    assertEquals(Wire.LINKS, frame[1]);
    ByteSource state = ByteSource.of(Arrays.copyOfRange(frame, 2, frame.length));
    assertEquals(self.toString(), state.readText(100));
    state.readLong();
    List<String> neighbours = new ArrayList<>();
    for (int n = state.readVarUInt(); n > 0; n--) {
      neighbours.add(state.readText(100));
    }
    return neighbours;
  }
}
