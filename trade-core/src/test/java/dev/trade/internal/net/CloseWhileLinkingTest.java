package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.internal.net.link.Wire;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A link whose handshake ends while its container closes is said GOODBYE to before it is closed, as
 * every other link of that container is: its peer sees an orderly leave, not a lost link.
 */
@Timeout(30)
class CloseWhileLinkingTest {

  @Test
  void aLinkThatComesUpWhileItsContainerClosesGetsAGoodbye() throws Exception {
    TRADEContainer c = Hubs.hubBuilder("leaving").build();
    String[] at = c.getServerAddresses().get(0).split("@");
    InetSocketAddress address = new InetSocketAddress(at[0], Integer.parseInt(at[1]));
    Thread closing = new Thread(c::close);
    try (RawPeer late = RawPeer.connect(c)) {
      RawPeer.Begun begun = late.begin("late", 1);
      closing.start();
      // It stops accepting connections once it counts as closing.
      Await.until(Duration.ofSeconds(10), () -> !accepts(address), "the container to close");
      late.finish(begun);
      byte[] frame;
      do { // what it may send first (its link state, a ping)
        frame = late.readFrame();
      } while (frame[0] != Wire.GOODBYE);
      assertEquals(Wire.GOODBYE, frame[0]);
    } finally {
      closing.join();
    }
  }

  private static boolean accepts(InetSocketAddress address) {
    try (Socket s = new Socket()) {
      s.connect(address, 1_000);
      return true;
    } catch (IOException e) {
      return false;
    }
  }
}
