package dev.trade.internal.net.mesh;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.net.LogCapture;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The line for a container that left names it by its name, as the other lines do; its id is DEBUG. */
class LeftLineTest {
  private final String self = UUID.randomUUID().toString();
  private final String arm = UUID.randomUUID().toString();
  private final Registry registry = new Registry(self, "self", "host");
  private final TableKeeper tables = new TableKeeper(registry, TimeUnit.SECONDS.toNanos(60));

  @Test
  void leftNamesTheContainerAndGivesItsIdAtDebugOnly() {
    ServiceDescriptor grip = new ServiceDescriptor(arm, "arm", "host", 1, "grip", List.of(),
        List.of(), "void", Set.of(), List.of());
    registry.applyTables(List.of(new Table(arm, 1, List.of(grip))), Map.of(arm, 1));
    try (LogCapture log = new LogCapture()) {
      tables.follow(Map.of(), Map.of(), 0);
      assertTrue(log.has(java.util.logging.Level.INFO, "container arm left or is not reachable any more"),
          log.tail());
      assertFalse(log.has(java.util.logging.Level.INFO, arm), log.tail());
      assertTrue(log.has(java.util.logging.Level.FINE, "the container that left is " + arm), log.tail());
    }
  }
}
