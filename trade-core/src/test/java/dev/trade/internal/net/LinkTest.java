package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** A link reports why it was closed: the first reason given to close(), not a generic "closed". */
class LinkTest {
  private ServerSocket server;
  private Socket near;
  private Socket far;

  @BeforeEach
  void connect() throws IOException {
    server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
    near = new Socket();
    near.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), server.getLocalPort()));
    far = server.accept();
  }

  @AfterEach
  void close() throws IOException {
    near.close();
    far.close();
    server.close();
  }

  private static Handshake.Peer peer(String name) {
    return new Handshake.Peer(UUID.randomUUID(), name, "host", List.of(), null); // no encryption
  }

  /** Records the reason the link reports when it closes; closes it on GOODBYE, as Network does. */
  private static final class Recorder implements Link.Handler {
    final CompletableFuture<String> reason = new CompletableFuture<>();

    @Override
    public void frame(Link link, int type, byte[] payload) {
      if (type == Wire.GOODBYE) {
        link.close("said goodbye");
      }
    }

    @Override
    public void closed(Link link, String why) {
      reason.complete(why);
    }
  }

  @Test
  void aLinkClosedHereReportsTheReasonGiven() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r);
    link.close("silent for 3012 ms (FAILURETIMEOUT=3000)");
    assertEquals("silent for 3012 ms (FAILURETIMEOUT=3000)", r.reason.get(5, TimeUnit.SECONDS));
    assertTrue(link.isClosed());
  }

  @Test
  void aLinkClosedByItsHandlerReportsThatReason() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r);
    far.getOutputStream().write(Frames.finish(Frames.start(Wire.GOODBYE, 0)));
    far.getOutputStream().flush();
    assertEquals("said goodbye", r.reason.get(5, TimeUnit.SECONDS));
  }

  @Test
  void aLinkClosedByThePeerSaysSo() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.start(r);
    far.close();
    assertEquals("connection closed by C", r.reason.get(5, TimeUnit.SECONDS));
  }

  @Test
  void onlyTheFirstReasonCounts() throws Exception {
    Link link = new Link(near, peer("C"), true, 1 << 20);
    Recorder r = new Recorder();
    link.close("duplicate link");
    link.close("container closing");
    link.start(r);
    assertEquals("duplicate link", r.reason.get(5, TimeUnit.SECONDS));
  }
}
