package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Wire;
import dev.trade.testing.Hubs;
import java.io.DataInputStream;
import java.io.EOFException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/** An authenticated peer whose call carries bytes that are not a value loses its connection. */
class MalformedCallTest {
  public static class Echo {
    final java.util.concurrent.atomic.AtomicInteger calls =
        new java.util.concurrent.atomic.AtomicInteger();

    @TRADEService
    public String echo(String s) {
      calls.incrementAndGet();
      return s;
    }
  }

  /**
   * A CALL that arrives with no time left (a timeout of 0 or less, which no sender writes) is not
   * run: it is answered at once with a timeout, and the link stays up.
   */
  @Test
  void aCallWithNoTimeLeftIsAnsweredWithATimeoutAndNotRun() throws Exception {
    try (TRADEContainer server = TRADEContainer.builder().name("server")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0")
        .property("CREDENTIALS", "secret").build()) {
      Echo echo = new Echo();
      server.registerAllServices(echo);
      String[] address = server.getServerAddresses().get(0).split("@");
      UUID me = UUID.randomUUID();
      try (Socket s = new Socket()) {
        s.connect(new InetSocketAddress(address[0], Integer.parseInt(address[1])), 2000);
        s.setSoTimeout(20_000);
        Handshake.Peer peer = new Handshake(new Handshake.Identity("diarc", me, "tester", "h",
            List.of(), false, false, 0), "secret").run(s.getInputStream(), s.getOutputStream(), true);
        DataInputStream in = new DataInputStream(s.getInputStream());
        for (int timeout : new int[] {0, -5, Integer.MIN_VALUE}) {
          ByteSink call = Frames.start(Wire.CALL, 64);
          Frames.writeRouting(call, me, peer.containerId(), Wire.MAX_HOPS);
          call.writeLong(7); // request id
          call.writeLong(RawPeer.firstUserServiceId(server));
          call.writeInt(timeout);
          call.writeVarUInt(1);
          call.writeByte(0x0A); // the tag of a STRING ...
          call.writeVarUInt(0); // ... that is empty
          s.getOutputStream().write(Frames.finish(call));
          assertEquals(Wire.FAILED_TIMEOUT, replyStatus(in), "timeout " + timeout);
        }
        assertEquals(0, echo.calls.get(), "run with no time left");
      }
    }
  }

  /** The status of the next REPLY, skipping replication frames. */
  private static int replyStatus(DataInputStream in) throws java.io.IOException {
    while (true) {
      byte[] body = new byte[in.readInt()];
      in.readFully(body);
      if (body[1] == Wire.REPLY) {
        return body[2 + Frames.ROUTING + 8];
      }
    }
  }

  @Test
  void malformedArgumentsGetAnErrorReplyAndTheConnectionIsClosed() throws Exception {
    try (TRADEContainer server = Hubs.hubBuilder("server")
        .property("CREDENTIALS", "secret").build()) {
      server.registerAllServices(new Echo()); // the container's first service
      String[] address = server.getServerAddresses().get(0).split("@");
      UUID me = UUID.randomUUID();
      try (Socket s = new Socket()) {
        s.connect(new InetSocketAddress(address[0], Integer.parseInt(address[1])), 2000);
        s.setSoTimeout(5000);
        Handshake.Peer peer = new Handshake(new Handshake.Identity("diarc", me, "tester", "h",
            List.of(), false, false, 0), "secret").run(s.getInputStream(), s.getOutputStream(), true);
        assertEquals(UUID.fromString(server.getId()), peer.containerId());

        ByteSink call = Frames.start(Wire.CALL, 64);
        Frames.writeRouting(call, me, peer.containerId(), Wire.MAX_HOPS);
        call.writeLong(7); // request id
        call.writeLong(RawPeer.firstUserServiceId(server)); // service id
        call.writeInt(1000);
        call.writeVarUInt(1);
        call.writeByte(0x7f); // not a value tag
        s.getOutputStream().write(Frames.finish(call));

        DataInputStream in = new DataInputStream(s.getInputStream());
        int status = -1;
        try {
          while (true) { // skip replication frames until the reply
            int length = in.readInt();
            byte[] body = new byte[length];
            in.readFully(body);
            if (body[1] == Wire.REPLY) {
              status = body[2 + Frames.ROUTING + 8];
              break;
            }
          }
        } catch (EOFException e) {
          throw new AssertionError("closed before replying", e);
        }
        assertEquals(Wire.FAILED_SERIALIZATION, status);
        assertThrows(EOFException.class, () -> {
          while (true) {
            in.readFully(new byte[in.readInt()]);
          }
        }, "the connection is closed after the reply");
      }
    }
  }
}
