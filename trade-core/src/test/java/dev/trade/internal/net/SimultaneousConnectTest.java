package dev.trade.internal.net;

import static dev.trade.internal.net.LinkThreads.readers;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.net.link.LinkReferee;
import dev.trade.testing.Await;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Two containers that each dial the other end up with one link, the same one on both sides. */
@Timeout(60)
class SimultaneousConnectTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  public static class Named {
    private final String name;

    Named(String name) {
      this.name = name;
    }

    @TRADEService
    public String whoAreYou() {
      return name;
    }
  }

  @Test
  void twoContainersDiallingEachOtherKeepExactlyOneLink() throws Exception {
    int[] ports = freePorts(2);
    try (TRADEContainer a = twin("twin-a", ports[0], ports[1]);
        TRADEContainer b = twin("twin-b", ports[1], ports[0])) {
      a.registerAllServices(new Named("twin-a"), "a");
      b.registerAllServices(new Named("twin-b"), "b");
      TRADEServiceConstraints fromA = new TRADEServiceConstraints().inGroups("a");
      TRADEServiceConstraints fromB = new TRADEServiceConstraints().inGroups("b");
      Await.until(WAIT, () -> !a.getAvailableServices(fromB).isEmpty()
          && !b.getAvailableServices(fromA).isEmpty(), "the services to cross");
      // Each link has one reader thread per side, named after the peer.
      Await.until(WAIT, () -> readers("twin-b") == 1 && readers("twin-a") == 1,
          "one link (readers in a: " + readers("twin-b") + ", in b: " + readers("twin-a") + ")");
      for (int i = 0; i < 50; i++) {
        assertEquals("twin-b", a.getAvailableService(fromB).call(String.class));
        assertEquals("twin-a", b.getAvailableService(fromA).call(String.class));
      }
      assertEquals(1, readers("twin-b"));
      assertEquals(1, readers("twin-a"));
    }
  }

  private static TRADEContainer twin(String name, int listen, int dial) {
    return TRADEContainer.builder().name(name).property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@" + listen).property("CONNECTCONTAINERS", "127.0.0.1@" + dial)
        .build();
  }

  /** Loopback ports that were free a moment ago. */
  private static int[] freePorts(int n) throws IOException {
    List<ServerSocket> sockets = new ArrayList<>();
    try {
      int[] ports = new int[n];
      for (int i = 0; i < n; i++) {
        ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        sockets.add(s);
        ports[i] = s.getLocalPort();
      }
      return ports;
    } finally {
      for (ServerSocket s : sockets) {
        s.close();
      }
    }
  }

  @Test
  void containerIdsAreOrderedAsUnsignedBytes() {
    // UUID.compareTo says the first is larger (it compares signed halves); RFC 4122 and other
    // languages say smaller, and the two sides of a duplicate link must agree.
    UUID low = UUID.fromString("7fffffff-ffff-ffff-ffff-ffffffffffff");
    UUID high = UUID.fromString("80000000-0000-0000-0000-000000000000");
    assertTrue(low.compareTo(high) > 0);
    assertTrue(LinkReferee.compareIds(low, high) < 0);
    assertTrue(LinkReferee.compareIds(high, low) > 0);
    UUID lowTail = UUID.fromString("00000000-0000-0000-7fff-ffffffffffff");
    UUID highTail = UUID.fromString("00000000-0000-0000-8000-000000000000");
    assertTrue(LinkReferee.compareIds(lowTail, highTail) < 0);
    assertEquals(0, LinkReferee.compareIds(low, UUID.fromString(low.toString())));
  }
}
