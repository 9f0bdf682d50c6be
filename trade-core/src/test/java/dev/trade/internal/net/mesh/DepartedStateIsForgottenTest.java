package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.Table;
import dev.trade.testing.FakeScheduler;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * What is kept of containers that left (their link states, tables, ids and that they were lost, for
 * the grace period) is forgotten when the grace ends, also when nothing changes afterwards: pruning
 * came only with route computations, so the states and tables of the last containers to leave
 * stayed for good, and a neighbour lost before its own state came was remembered as lost for good
 * (a 1,000,000-input link fuzzing ended some MB above where it began, and never came back).
 */
class DepartedStateIsForgottenTest {
  private static final long HOLD_DOWN = TimeUnit.SECONDS.toNanos(1);
  private static final long GRACE = TimeUnit.SECONDS.toNanos(60);
  private final FakeScheduler clock = new FakeScheduler();
  private final String self = UUID.randomUUID().toString();
  private final Topology topology = new Topology(self, HOLD_DOWN, clock::nanoTime);
  private final Registry registry = new Registry(self, "self", "host");
  private final TableKeeper tables = new TableKeeper(registry, GRACE);
  private final Routing routing = new Routing(topology, tables, registry,
      new FloodFilter(topology, registry, tables), gone -> { },
      (task, delayNanos) -> clock.timer().schedule(task, delayNanos, TimeUnit.NANOSECONDS),
      (hop, owner) -> { }, owner -> { }, GRACE);

  @Test
  void theLastContainersToLeaveAreForgottenOnceTheGraceEnds() {
    for (int i = 0; i < 3; i++) {
      String peer = UUID.randomUUID().toString();
      linkAndLeave(peer);
      assertNotNull(topology.state(peer), "kept for the grace");
      assertEquals(1, tables.known().size(), "its table kept for the grace");

      clock.advance(Duration.ofNanos(GRACE - HOLD_DOWN)); // nothing happens meanwhile
      assertNotNull(topology.state(peer), "kept until the grace ends");

      clock.advance(Duration.ofSeconds(3)); // the grace, counted from the first prune after it left
      assertNull(topology.state(peer), "forgotten " + i);
      assertEquals(List.of(), tables.known(), "table forgotten " + i);
      assertFalse(routing.knowsId(peer), "id forgotten " + i);
    }
    clock.advance(Duration.ofMinutes(5));
    assertEquals(0, clock.pending(), "nothing left to prune, nothing scheduled");
  }

  @Test
  void aNeighbourThatLeftBeforeItsStateCameIsForgottenToo() {
    for (int i = 0; i < 3; i++) {
      String peer = UUID.randomUUID().toString();
      topology.setOwnNeighbours(Set.of(peer));
      routing.follow();
      assertNotNull(routing.route(peer));
      topology.setOwnNeighbours(Set.of());
      routing.follow();
      assertTrue(topology.isLost(peer), "lost: its state, should one come, is not given on");

      clock.advance(Duration.ofNanos(GRACE + TimeUnit.SECONDS.toNanos(3)));
      assertFalse(topology.isLost(peer), "forgotten " + i);
      assertFalse(routing.knowsId(peer), "id forgotten " + i);
    }
    clock.advance(Duration.ofMinutes(5));
    assertEquals(0, clock.pending(), "nothing left to prune, nothing scheduled");
  }

  @Test
  void aContainerThatComesBackIsNotForgotten() {
    String peer = UUID.randomUUID().toString();
    linkAndLeave(peer);
    topology.setOwnNeighbours(Set.of(peer)); // back before the grace ends
    routing.follow();
    clock.advance(Duration.ofNanos(2 * GRACE));
    assertNotNull(topology.state(peer));
    assertNotNull(routing.route(peer));
  }

  /** {@code peer} links, lists its services and leaves, all at one moment. */
  private void linkAndLeave(String peer) {
    topology.setOwnNeighbours(Set.of(peer));
    topology.apply(new Topology.LinkState(peer, 1, Set.of(self)));
    routing.follow();
    tables.table(new Table(peer, 1, List.of()), routing.route(peer), clock.nanoTime());
    assertNotNull(routing.route(peer));
    assertEquals(1, registry.remoteTables().size());
    topology.setOwnNeighbours(Set.of());
    routing.follow();
    assertNull(routing.route(peer));
  }
}
