package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.registry.Registry;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.Callable;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * A container held down after it became unreachable is routed again when its hold-down ends, even
 * when another hold-down ended first and changed no route: nothing else recomputes routes in a
 * quiet system, and such a container stayed unreachable for good (seen as one container of 100
 * lacking two services a minute after the others had converged).
 */
class HoldDownEndsTest {
  /**
   * Long enough that b's hold-down is still in force when c's begins (the two steps below are
   * milliseconds apart), which is what the old code got wrong; short, since the test waits for it.
   */
  private static final long HOLD_DOWN = TimeUnit.SECONDS.toNanos(1);
  private static final long LONG = TimeUnit.SECONDS.toNanos(60);
  private final UUID self = UUID.randomUUID();
  private final String n = UUID.randomUUID().toString();
  private final String b = UUID.randomUUID().toString();
  private final String c = UUID.randomUUID().toString();
  /** The control thread: routing and topology are used on it alone, as in a container. */
  private final ScheduledExecutorService control = Executors.newSingleThreadScheduledExecutor();
  private final Topology topology = new Topology(self.toString(), HOLD_DOWN);
  private final Registry registry = new Registry(self.toString(), "self", "host");
  private final TableKeeper tables = new TableKeeper(registry, LONG);
  private final Routing routing = new Routing(topology, tables, registry,
      new FloodFilter(topology, registry, tables),
      gone -> { },
      (task, delayNanos) -> control.schedule(task, delayNanos, TimeUnit.NANOSECONDS),
      (hop, owner) -> { }, owner -> { }, LONG);

  @AfterEach
  void close() {
    control.shutdownNow();
  }

  @Test
  void theSecondOfTwoHoldDownsEndsToo() {
    onControl(() -> {
      topology.setOwnNeighbours(Set.of(n));
      topology.apply(new Topology.LinkState(n, 1, Set.of(self.toString(), b, c)));
      topology.apply(new Topology.LinkState(b, 1, Set.of(n)));
      topology.apply(new Topology.LinkState(c, 1, Set.of(n)));
      routing.follow();
      assertNotNull(routing.route(b));
      assertNotNull(routing.route(c));
      // b drops its link for good: held down, and unreachable after its hold-down too.
      topology.apply(new Topology.LinkState(b, 2, Set.of()));
      routing.follow();
      assertNull(routing.route(b));
      return null;
    });
    long first = System.nanoTime();
    Await.until(Duration.ofSeconds(1), () -> System.nanoTime() != first, "time passes");
    onControl(() -> {
      // n loses c and links it again before c's own state changes: c is held down, and its
      // hold-down ends after b's.
      topology.apply(new Topology.LinkState(n, 2, Set.of(self.toString(), b)));
      routing.follow();
      assertNull(routing.route(c));
      topology.apply(new Topology.LinkState(n, 3, Set.of(self.toString(), b, c)));
      routing.follow();
      assertNull(routing.route(c), "held down");
      return null;
    });
    Await.until(Duration.ofSeconds(5), () -> onControl(() -> routing.route(c) != null),
        "c routed again once its hold-down ended");
    assertTrue(onControl(() -> routing.route(b) == null), "b still unreachable");
  }

  private <T> T onControl(Callable<T> task) {
    try {
      return control.submit(task).get(5, TimeUnit.SECONDS);
    } catch (Exception e) {
      throw new AssertionError(e);
    }
  }
}
