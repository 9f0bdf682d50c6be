package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.testing.Hubs;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import org.junit.jupiter.api.Test;

/**
 * A party without credentials cannot join two containers by relaying their handshakes: it opens a
 * connection to each and pipes the bytes of one to the other, so that each container's HELLO and
 * AUTH reach the other as if that one had connected to it. Both containers accepted, and the AUTH
 * proof names the sender's role, so neither proof passes: both refuse, and neither links the other
 * (before the role was in the proof, both took the pipe for an authentic link). On loopback.
 */
class RelayTest {

  @Test
  void twoContainersJoinedByACrossPipeRefuseEachOther() throws Exception {
    try (TRADEContainer a = listening("a"); TRADEContainer b = listening("b");
        Socket toA = connect(a); Socket toB = connect(b)) {
      Thread aToB = pipe(toA.getInputStream(), toB.getOutputStream());
      Thread bToA = pipe(toB.getInputStream(), toA.getOutputStream());
      // Each refuses the other's AUTH and closes; the pipes end at the end of their streams.
      aToB.join(10_000);
      bToA.join(10_000);
      assertFalse(aToB.isAlive() || bToA.isAlive(), "the relayed handshake is still open");
      assertTrue(a.getNeighbours().isEmpty(), "a linked " + a.getNeighbours());
      assertTrue(b.getNeighbours().isEmpty(), "b linked " + b.getNeighbours());
    }
  }

  private static TRADEContainer listening(String name) {
    return Hubs.hubBuilder(name).property("CREDENTIALS", "only-a-and-b-know").build();
  }

  private static Socket connect(TRADEContainer c) throws IOException {
    String[] at = c.getServerAddresses().get(0).split("@");
    Socket s = new Socket();
    s.connect(new InetSocketAddress(at[0], Integer.parseInt(at[1])), 5_000);
    return s;
  }

  /** Copies until the end of {@code in} or a failure, then closes {@code out}'s socket side. */
  private static Thread pipe(InputStream in, OutputStream out) {
    Thread t = new Thread(() -> {
      byte[] buf = new byte[4096];
      try (out) {
        for (int n; (n = in.read(buf)) >= 0; ) {
          out.write(buf, 0, n);
          out.flush();
        }
      } catch (IOException e) {
        // One side closed: the pipe ends.
      }
    }, "relay");
    t.setDaemon(true);
    t.start();
    return t;
  }
}
