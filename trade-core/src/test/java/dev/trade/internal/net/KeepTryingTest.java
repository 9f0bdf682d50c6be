package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.testing.Await;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.logging.Level;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * TRADE 1.1.1's KEEPTRYING: a configured address whose handshake fails is dialled again while it is
 * true (the default), and once only, with a WARNING saying so, while it is false.
 */
@Timeout(60)
class KeepTryingTest {
  private static final Duration WAIT = Duration.ofSeconds(20);

  /** A listener on loopback that accepts connections and closes them at once, counting them. */
  private static final class Refuser implements AutoCloseable {
    final ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
    final AtomicInteger accepted = new AtomicInteger();

    Refuser() throws IOException {
      Thread t = new Thread(() -> {
        while (!server.isClosed()) {
          try (Socket s = server.accept()) {
            accepted.incrementAndGet();
          } catch (IOException closed) {
            return;
          }
        }
      }, "refuser");
      t.setDaemon(true);
      t.start();
    }

    String address() {
      return "127.0.0.1@" + server.getLocalPort();
    }

    @Override
    public void close() throws IOException {
      server.close();
    }
  }

  private static TRADEContainer dialling(Refuser peer, String keepTrying) {
    return TRADEContainer.builder().name("dialler").property("CONNECTCONTAINERS", peer.address())
        .property("KEEPTRYING", keepTrying).build();
  }

  @Test
  void byDefaultAFailedAddressIsDialledAgain() throws Exception {
    try (Refuser peer = new Refuser(); TRADEContainer c = dialling(peer, "true")) {
      Await.until(WAIT, () -> peer.accepted.get() >= 2, "a second attempt");
    }
  }

  @Test
  void withoutKeepTryingItIsDialledOnceAndTheWarningSaysSo() throws Exception {
    try (LogCapture log = new LogCapture(); Refuser peer = new Refuser();
        TRADEContainer c = dialling(peer, "false")) {
      // The capture hears every container in this JVM, so only lines naming this peer count.
      String to = "cannot connect to /127.0.0.1:" + peer.server.getLocalPort() + ":";
      Await.until(WAIT, () -> log.has(Level.WARNING, to, "not retrying (KEEPTRYING=false)"),
          "the warning; have " + log.tail());
      assertTrue(peer.accepted.get() == 1, "attempts: " + peer.accepted.get());
      // A retry is scheduled, and logged, in the same step that reports a failure: none was.
      assertFalse(log.has(Level.FINE, to, "retrying") || log.has(Level.INFO, to, "retrying"),
          log.tail());
    }
  }
}
