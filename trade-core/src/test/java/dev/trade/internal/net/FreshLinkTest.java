package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.Arrays;
import java.util.UUID;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Calls are served on the reader's path while link states are applied on the control thread, so
 * a neighbour's first CALL can overtake its LINKS, and a call forwarded along a path that just
 * formed can arrive before the provider has a route back. The REPLY must still find its way back.
 */
@Timeout(30)
class FreshLinkTest {

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  @Test
  void aDirectNeighbourIsAnsweredBeforeItsLinkStateArrives() throws Exception {
    answeredOverTheLinkItCameBy(false);
  }

  @Test
  void aCallForwardedFromAnUnknownContainerIsAnsweredBackTheWayItCame() throws Exception {
    answeredOverTheLinkItCameBy(true);
  }

  /** @param forwarded whether the call comes from a container behind the peer, unknown to the provider */
  private void answeredOverTheLinkItCameBy(boolean forwarded) throws Exception {
    try (TRADEContainer server = Hubs.hubBuilder("provider").build()) {
      server.registerAllServices(new Arm()); // its first service
      String[] a = server.getServerAddresses().get(0).split("@");
      try (RawPeer p = RawPeer.connect(new InetSocketAddress(a[0], Integer.parseInt(a[1])))) {
        Handshake.Peer provider = p.handshake("early");
        // No LINKS from us at all: the provider cannot route to us, only answer over the link.
        Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
        UUID caller = forwarded ? UUID.randomUUID() : p.id;
        RemoteCalls us = new RemoteCalls(caller, codec, null, null, null, 1 << 20);
        p.send(us.callFrame(provider.containerId(), 7, RawPeer.firstUserServiceId(server), 5_000,
            new Object[] {3}));
        long deadline = System.nanoTime() + Duration.ofSeconds(5).toNanos();
        byte[] frame;
        do { // skip the provider's LINKS, TABLE, PING...
          frame = p.readFrame();
        } while (frame[0] != Wire.REPLY && System.nanoTime() < deadline);
        assertEquals(Wire.REPLY, frame[0], "no reply");
        byte[] reply = Arrays.copyOfRange(frame, 1, frame.length);
        assertEquals(caller, Frames.destination(reply));
        assertEquals(7, Frames.requestId(reply));
        ByteSource body = ByteSource.of(reply, Frames.ROUTING + 8, reply.length - Frames.ROUTING - 8);
        assertEquals(Wire.OK, body.readUnsignedByte());
        assertEquals(true, codec.read(body, getClass().getClassLoader()));
      }
    }
  }
}
