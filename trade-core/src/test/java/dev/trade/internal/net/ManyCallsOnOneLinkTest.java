package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.io.ByteArrayOutputStream;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.UUID;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A neighbour that sends more calls to a slow service than end: the provider serves at most
 * {@link RemoteCalls#MAX_SERVED_PER_LINK} of them at once beside the link's reading thread (each
 * takes a thread), answers the others at once as not available now, and goes on reading the link.
 * Every call gets its one reply; none is lost. On loopback.
 */
class ManyCallsOnOneLinkTest {
  private static final int MORE = 40;

  /** A service that holds every call until the test lets them go. */
  public static class Gate {
    final AtomicInteger inside = new AtomicInteger();
    final CountDownLatch open = new CountDownLatch(1);

    @TRADEService
    public int pass() throws InterruptedException {
      inside.incrementAndGet();
      return open.await(60, TimeUnit.SECONDS) ? 1 : 0;
    }
  }

  @Test
  @Timeout(90)
  void callsBeyondTheBoundAreAnsweredAtOnceAndTheRestWhenTheyEnd() throws Exception {
    Gate gate = new Gate();
    try (TRADEContainer provider = Hubs.hubBuilder("provider")
        // The caller sends nothing once its calls are out: on a slow machine the provider must
        // not find it silent before the last of them entered the gate.
        .property("FAILURETIMEOUT", "60000").build()) {
      provider.registerAllServices(gate); // the container's first service
      String[] at = provider.getServerAddresses().get(0).split("@");
      try (RawPeer caller = RawPeer.connect(new InetSocketAddress(at[0], Integer.parseInt(at[1])))) {
        UUID providerId = caller.handshake("caller").containerId();
        int calls = RemoteCalls.MAX_SERVED_PER_LINK + MORE;
        ByteArrayOutputStream frames = new ByteArrayOutputStream();
        for (int id = 1; id <= calls; id++) {
          ByteSink call = Frames.start(Wire.CALL, 64);
          Frames.writeRouting(call, caller.id, providerId, Wire.MAX_HOPS);
          call.writeLong(id); // request id
          call.writeLong(RawPeer.firstUserServiceId(provider)); // service id
          call.writeInt(60_000);
          call.writeVarUInt(0);
          frames.write(Frames.finish(call));
        }
        caller.send(frames.toByteArray());

        int[] statuses = new int[calls + 1];
        int busy = 0;
        while (busy < MORE) { // the calls beyond the bound, answered while the others wait
          int status = nextReply(caller, statuses);
          assertEquals(Wire.FAILED_UNAVAILABLE, status, "a reply before the gate opened");
          busy++;
        }
        Await.until(Duration.ofSeconds(30),
            () -> gate.inside.get() == RemoteCalls.MAX_SERVED_PER_LINK, "the calls inside the gate");
        gate.open.countDown();
        for (int i = 0; i < RemoteCalls.MAX_SERVED_PER_LINK; i++) {
          assertEquals(Wire.OK, nextReply(caller, statuses), "a reply after the gate opened");
        }
        for (int id = 1; id <= calls; id++) {
          assertTrue(statuses[id] != 0, "no reply to call " + id);
        }
        assertEquals(RemoteCalls.MAX_SERVED_PER_LINK, gate.inside.get(), "calls served");
      }
    }
  }

  /** Reads frames until a REPLY, notes its status under its request id, and returns the status. */
  private static int nextReply(RawPeer caller, int[] statuses) throws Exception {
    while (true) {
      byte[] f = caller.readFrame();
      if (f[0] == Wire.REPLY) {
        ByteSource in = ByteSource.of(f, 1 + Frames.ROUTING, f.length - 1 - Frames.ROUTING);
        int id = (int) in.readLong();
        int status = in.readUnsignedByte();
        assertEquals(0, statuses[id], "a second reply to call " + id);
        statuses[id] = status + 1_000; // never 0
        return status;
      }
    }
  }
}
