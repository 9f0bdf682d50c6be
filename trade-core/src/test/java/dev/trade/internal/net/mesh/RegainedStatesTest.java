package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import dev.trade.internal.registry.Registry;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Routing passes on the state of a container it lost once it reaches it again: while it was lost,
 * new neighbours were not given that state ({@link Topology#statesToShare}), and nothing else would
 * bring it to them unless the container's own links changed.
 */
class RegainedStatesTest {
  private static final long LONG = TimeUnit.SECONDS.toNanos(60);
  private final UUID self = UUID.randomUUID();
  private final String b = UUID.randomUUID().toString();
  private final String c = UUID.randomUUID().toString();
  private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
  private final Topology topology = new Topology(self.toString(), LONG);
  private final Registry registry = new Registry(self.toString(), "self", "host");
  private final TableKeeper tables = new TableKeeper(registry, LONG);
  private final List<String> passedOn = new CopyOnWriteArrayList<>();
  private final Routing routing = new Routing(topology, tables, registry,
      new FloodFilter(topology, registry, tables),
      gone -> { },
      (task, delayNanos) -> { }, (hop, owner) -> { }, passedOn::add, LONG);

  @AfterEach
  void close() {
    timer.shutdownNow();
  }

  @Test
  void aLostContainersStateIsPassedOnOnceItIsReachableAgain() {
    topology.setOwnNeighbours(Set.of(c));
    topology.apply(new Topology.LinkState(c, 1, Set.of(self.toString(), b)));
    topology.apply(new Topology.LinkState(b, 1, Set.of(c)));
    routing.follow();
    assertEquals(c, routing.route(b).nextHop());
    topology.setOwnNeighbours(Set.of()); // c died
    routing.follow();
    assertNull(routing.route(b));
    assertEquals(List.of(), passedOn, "nothing regained yet");
    topology.setOwnNeighbours(Set.of(b)); // a new link to b
    routing.follow();
    assertEquals(List.of(b), passedOn);
    routing.follow();
    assertEquals(List.of(b), passedOn, "once");
  }
}
