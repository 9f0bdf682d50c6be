package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.testing.Await;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ConnectorTest {

  @Test
  void retryingNowReplacesTheRetryChainInsteadOfAddingOne() throws Exception {
    InetSocketAddress nobody; // a loopback port that refuses connections
    try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      nobody = (InetSocketAddress) s.getLocalSocketAddress();
    }
    AtomicInteger attempts = new AtomicInteger(); // every attempt asks the sink first
    ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
    ExecutorService workers = Executors.newCachedThreadPool();
    Handshake handshake = new Handshake(new Handshake.Identity("diarc", UUID.randomUUID(), "dialler",
        "localhost", List.of()), "diarcUser");
    Connector connector = new Connector("dialler", handshake, 1_000, workers, timer,
        new Connector.Sink() {
          @Override
          public void linked(Socket socket, Handshake.Peer peer, boolean initiatedHere) {
            throw new AssertionError("nobody listens there");
          }

          @Override
          public boolean isLinked(InetSocketAddress address) {
            attempts.incrementAndGet();
            return false;
          }

          @Override
          public void handshakeBegun(UUID peer) {
            throw new AssertionError("nobody answers there");
          }

          @Override
          public void handshakeEnded(UUID peer) {
            throw new AssertionError("nobody answers there");
          }
        });
    try {
      connector.keepConnected(nobody);
      Await.until(Duration.ofSeconds(30), () -> attempts.get() >= 1, "the first attempt");
      for (int i = 0; i < 20; i++) { // as if 20 links were lost
        connector.retryNow();
      }
      long start = System.nanoTime();
      int before = attempts.get();
      // One chain backs off 50, 100, 200, 400 ms between attempts; 21 chains would be done at once.
      Await.until(Duration.ofSeconds(30), () -> attempts.get() >= before + 5, "5 more attempts");
      long tookMs = (System.nanoTime() - start) / 1_000_000;
      assertTrue(tookMs >= 500, "5 attempts in " + tookMs + " ms: several retry chains are running");
    } finally {
      connector.close();
      timer.shutdownNow();
      workers.shutdownNow();
    }
  }
}
