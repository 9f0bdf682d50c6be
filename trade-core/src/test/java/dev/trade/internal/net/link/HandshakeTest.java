package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.testing.Hubs;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class HandshakeTest {

  private static Handshake declaring(String name, int maxFrame) {
    return new Handshake(new Handshake.Identity("diarc", UUID.randomUUID(), name, "localhost",
        List.of(), false, true, maxFrame), "diarcUser");
  }

  /** Runs both handshakes over a loopback connection; the opening side's result first. */
  private static Handshake.Peer[] shake(Handshake opening, Handshake accepting) throws Exception {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Socket out = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
        Socket in = server.accept()) {
      out.setSoTimeout(10_000);
      in.setSoTimeout(10_000);
      CompletableFuture<Handshake.Peer> accepted = CompletableFuture.supplyAsync(() -> {
        try {
          return accepting.run(in.getInputStream(), in.getOutputStream(), false);
        } catch (Exception e) {
          throw new IllegalStateException(e);
        }
      });
      Handshake.Peer opened = opening.run(out.getInputStream(), out.getOutputStream(), true);
      return new Handshake.Peer[] {opened, accepted.get(10, TimeUnit.SECONDS)};
    }
  }

  @Test
  void eachSideLearnsTheLargestFrameTheOtherAccepts() throws Exception {
    Handshake.Peer[] peers = shake(declaring("big", 1 << 26), declaring("small", 65_536));
    assertEquals(65_536, peers[0].maxFrame());
    assertEquals(1 << 26, peers[1].maxFrame());
  }

  @Test
  void aHelloWithoutAFrameLimitStillLinksAndLeavesTheLimitUnknown() throws Exception {
    Handshake.Peer[] peers = shake(declaring("silent", 0), declaring("small", 65_536));
    assertEquals(65_536, peers[0].maxFrame());
    assertEquals(0, peers[1].maxFrame());
  }

  @Test
  void aFrameLimitBelowTheSmallestAllowedIsRefusedAsMalformed() throws Exception {
    Handshake.Failure failure = assertThrows(Handshake.Failure.class,
        () -> shake(declaring("fine", 65_536), declaring("tiny", 512)));
    assertEquals(Wire.REFUSE_MALFORMED, failure.reason);
    assertTrue(failure.getMessage().contains("frame limit 512 below 1024"), failure.getMessage());
  }

  @Test
  void aHelloThatAnnouncesAFrameLimitAndEndsBeforeItIsRefusedAsMalformed() throws Exception {
    assertRefusedAsMalformedWithFlagAndNothingAfter(4);
  }

  @Test
  void aHelloThatAnnouncesADialNumberAndEndsBeforeItIsRefusedAsMalformed() throws Exception {
    assertRefusedAsMalformedWithFlagAndNothingAfter(8);
  }

  private static void assertRefusedAsMalformedWithFlagAndNothingAfter(int flag) throws Exception {
    Handshake sender = declaring("cut", 0);
    byte[] hello = sender.hello(new byte[32], 0);
    hello[hello.length - 1] |= flag; // the flag, without the field it announces
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        Socket out = new Socket(InetAddress.getLoopbackAddress(), server.getLocalPort());
        Socket in = server.accept()) {
      in.setSoTimeout(10_000);
      Handshake.writeFrame(new java.io.DataOutputStream(out.getOutputStream()), Wire.HELLO, hello);
      Handshake.Failure failure = assertThrows(Handshake.Failure.class,
          () -> declaring("fine", 65_536).run(in.getInputStream(), in.getOutputStream(), false));
      assertEquals(Wire.REFUSE_MALFORMED, failure.reason);
      assertTrue(failure.getMessage().startsWith("malformed HELLO"), failure.getMessage());
    }
  }

  @Test
  void theOpeningSideNumbersItsDialsAndBothEndsLearnTheNumber() throws Exception {
    Handshake dialler = declaring("dialler", 65_536);
    for (long n = 1; n <= 3; n++) {
      Handshake.Peer[] peers = shake(dialler, declaring("dialled", 65_536));
      assertEquals(n, peers[0].dial(), "the number at the side that dialled");
      assertEquals(n, peers[1].dial(), "the number at the side that was dialled");
    }
    // Dialled, it numbers nothing: the number is the other side's.
    Handshake.Peer[] peers = shake(declaring("other", 65_536), dialler);
    assertEquals(1, peers[0].dial());
    assertEquals(1, peers[1].dial());
  }

  @Test
  void fieldsLongerThanAHelloHoldsAreRefusedWhenTheContainerIsBuilt() {
    // 100 characters of 3 bytes each: 300 bytes of UTF-8, more than a str8 holds.
    String name = "\u2603".repeat(100);
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> Hubs.hubBuilder(name).build());
    // The configuration refuses it first, naming the key and the limit.
    assertTrue(e.getMessage().startsWith("CONTAINERNAME="), e.getMessage());
    assertTrue(e.getMessage().endsWith("expected a name of at most 255 bytes without control"
        + " characters"), e.getMessage());

    e = assertThrows(IllegalArgumentException.class, () -> new Handshake(new Handshake.Identity(
        "s".repeat(256), UUID.randomUUID(), "arm", "localhost", List.of()), "diarcUser"));
    assertTrue(e.getMessage().startsWith("TRADESYSID is 256 bytes long"), e.getMessage());
  }

  @Test
  void fieldsOfExactly255BytesAreFine() {
    new Handshake(new Handshake.Identity("s".repeat(255), UUID.randomUUID(), "n".repeat(255),
        "h".repeat(255), List.of()), "diarcUser");
  }
}
