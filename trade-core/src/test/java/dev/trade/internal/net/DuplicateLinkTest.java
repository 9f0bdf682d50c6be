package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import java.io.IOException;
import java.io.InputStream;
import java.time.Duration;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A second link to a container that is linked already replaces the first in one step: a caller
 * looking up its next hop meanwhile finds one of the two, never none (its call would fail at once
 * as "not reachable", for a container that was reachable all along).
 */
@Timeout(60)
class DuplicateLinkTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private static final int LINKS = 300;

  @Test
  void aNeighbourThatLinksAgainIsNeverMissingWhileTheLinksAreSwapped() throws Exception {
    // The smallest id: of two links it dialled, the container keeps the newer.
    UUID twin = new UUID(0, 1);
    String id = twin.toString();
    try (TRADEContainer c = TRADEContainer.builder().name("swapper")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0").build()) {
      RawPeer linked = RawPeer.connect(c, twin);
      linked.handshake("twin");
      Deadline.await(WAIT, () -> c.getNeighbours().contains(id), "the first link");
      AtomicBoolean done = new AtomicBoolean();
      AtomicInteger missing = new AtomicInteger();
      Thread watcher = new Thread(() -> {
        while (!done.get()) {
          if (!c.getNeighbours().contains(id)) {
            missing.incrementAndGet();
          }
        }
      });
      watcher.start();
      try {
        for (int i = 0; i < LINKS; i++) {
          RawPeer next = RawPeer.connect(c, twin);
          next.handshake("twin");
          readToTheEnd(linked); // the container closed the link it replaced
          linked.close();
          linked = next;
        }
      } finally {
        done.set(true);
        watcher.join();
        linked.close();
      }
      assertEquals(0, missing.get(), "times the neighbour was missing while " + LINKS
          + " links replaced one another");
    }
  }

  private static void readToTheEnd(RawPeer peer) throws IOException {
    peer.socket.setSoTimeout((int) WAIT.toMillis());
    InputStream in = peer.socket.getInputStream();
    byte[] buffer = new byte[8192];
    while (in.read(buffer) >= 0) {
      // What the container sent before it closed: not looked at.
    }
  }
}
