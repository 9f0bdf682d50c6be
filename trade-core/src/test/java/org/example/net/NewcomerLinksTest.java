package org.example.net;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.discovery.LoopbackMulticast;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A container that joins a quiet system larger than a full mesh makes its overlay links at once,
 * with the containers that answered its announcement. Before, it waited until it had heard nearly
 * every container, which in a quiet system is the others' next announcement (BROADCASTINTERVAL,
 * 3 s by default) or three seconds, and lived on its first link meanwhile.
 */
class NewcomerLinksTest {
  private static final int N = 16;
  private static final TRADEServiceConstraints WHO = new TRADEServiceConstraints().name("whoAmI");
  private final List<TRADEContainer> containers = new ArrayList<>();

  @BeforeEach
  void multicast() {
    LoopbackMulticast.assumeUsable();
  }

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
  }

  @Test
  void aNewcomerMakesItsOverlayLinksAtOnceNotAfterItsHold() throws TRADEException, InterruptedException {
    Swarm swarm = Swarm.start(N, containers);
    long built = System.nanoTime();
    for (TRADEContainer c : containers) {
      Await.until(Duration.ofSeconds(30), () -> c.getAvailableServices(WHO).size() == N,
          "all services on " + c.getName());
    }
    // Quiet: every container has heard every other one, at the latest at the others' announcement
    // one interval (3 s) after they started, with 2 s for a busy machine. A container answers by
    // what it has heard.
    sleepUntil(built + TimeUnit.MILLISECONDS.toNanos(5_000));
    TRADEContainer newcomer = swarm.join("newcomer");
    long joined = System.nanoTime();
    containers.add(newcomer);
    Await.until(Duration.ofSeconds(30), () -> newcomer.getAvailableServices(WHO).size() == N + 1,
        "all services on the newcomer");
    // Not waiting for an event but watching that none comes: the links 1.5 s after joining, and
    // those once the hold (3 s at most) is over. Answers come within milliseconds, and the newcomer
    // dials its first contact at once and the others after 100 ms of answers; before, it dialled
    // the others only once the hold was over (1.9 to 3 s in a quiet system of 16).
    sleepUntil(joined + TimeUnit.MILLISECONDS.toNanos(1_500));
    Set<String> early = Set.copyOf(newcomer.getNeighbours());
    sleepUntil(joined + TimeUnit.MILLISECONDS.toNanos(3_500));
    Set<String> later = Set.copyOf(newcomer.getNeighbours());
    assertTrue(early.containsAll(later), "linked after the hold: " + later + ", before: " + early);
    assertTrue(later.size() < N, "a full mesh: " + later.size() + " links");
  }

  private static void sleepUntil(long nanoTime) throws InterruptedException {
    long left = nanoTime - System.nanoTime();
    if (left > 0) {
      TimeUnit.NANOSECONDS.sleep(left);
    }
  }
}
