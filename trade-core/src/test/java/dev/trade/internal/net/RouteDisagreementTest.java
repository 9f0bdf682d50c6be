package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * While a link comes or goes, two neighbours can each have the other on their shortest path to a
 * container: a call passed back and forth between them would go round until its hops ran out and
 * fail as "not reachable". A container whose next hop for a call is the neighbour it came from
 * waits for routes to settle instead, and then passes it on the new way.
 */
@Timeout(30)
class RouteDisagreementTest {
  private static final Duration WAIT = Duration.ofSeconds(5);

  @Test
  void aCallWhoseNextHopIsTheNeighbourItCameFromWaitsForRoutesToSettle() throws Exception {
    Codec tables = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.DESCRIPTORS);
    String far = UUID.randomUUID().toString();
    String beyond = UUID.randomUUID().toString();
    try (TRADEContainer x = Hubs.hubBuilder("x").build();
        RawPeer a = RawPeer.connect(x);
        RawPeer b = RawPeer.connect(x)) {
      a.handshake("a");
      b.handshake("b");
      String xId = x.getId();
      String aId = a.id.toString();
      String bId = b.id.toString();
      // x - a - far is shorter than x - b - beyond - far: x's way to far is through a.
      b.send(StateFrames.links(new Topology.LinkState(bId, 1, Set.of(xId, beyond))));
      b.send(StateFrames.links(new Topology.LinkState(beyond, 1, Set.of(bId, far))));
      a.send(StateFrames.links(new Topology.LinkState(aId, 1, Set.of(xId, far))));
      a.send(StateFrames.links(new Topology.LinkState(far, 1, Set.of(aId, beyond))));
      a.send(StateFrames.table(tables, new Table(far, 1, List.of(new ServiceDescriptor(far, "far",
          "host", 1, "farProbe", List.of(), List.of(), "int", Set.of(), List.of())))));
      Await.until(WAIT, () -> x.getAvailableServices(new TRADEServiceConstraints()
          .name("farProbe")).stream().anyMatch(s -> s.getDistance() == 2), "far, through a");

      // a passes x a call for far, as if a's own link to far had just gone and a's view of it
      // still had x on the way; then the link state that says so.
      Codec values = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
      byte[] call = new RemoteCalls(a.id, values, null, null, null, 1 << 20)
          .callFrame(UUID.fromString(far), 7, 1, 5_000, new Object[0]);
      a.send(call);
      a.send(StateFrames.links(new Topology.LinkState(aId, 2, Set.of(xId))));

      byte[] passed;
      do { // link states, tables and pings first
        passed = b.readFrame();
      } while (passed[0] != Wire.CALL);
      byte[] payload = Arrays.copyOfRange(passed, 1, passed.length);
      assertEquals(UUID.fromString(far), Frames.destination(payload));
      assertEquals(7, Frames.requestId(payload));
      int timeout = ByteBuffer.wrap(payload).getInt(Frames.ROUTING + 16);
      assertTrue(timeout < 5_000 && timeout > 4_000, "the wait counts against the timeout: "
          + timeout);
    }
  }
}
