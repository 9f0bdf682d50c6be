package dev.trade.internal.registry;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** onLocalhost, notOnLocalhost and notOnHost against services on this host and on others. */
class HostConstraintsTest {
  private final Registry registry = new Registry("self", "self", "robot1");

  private static ServiceDescriptor on(String owner, String host, String name) {
    return new ServiceDescriptor(owner, owner, host, 1, name, List.of(), List.of(), "int", Set.of(),
        List.of());
  }

  private List<String> find(Boolean localhost, Set<String> notOnHosts) {
    Query q = new Query(null, null, null, Set.of(), Set.of(), false, null, localhost, notOnHosts,
        List.of(), List.of());
    return registry.find(null, q).stream().map(e -> e.descriptor().name()).sorted().toList();
  }

  @Test
  void hostsAreComparedWithTheLookingUpContainersHost() {
    registry.applyTables(List.of(new Table("b", 1, List.of(on("b", "robot1", "neighbour"))),
        new Table("c", 1, List.of(on("c", "robot2", "far")))), Map.of("b", 1, "c", 1));
    assertEquals(List.of("far", "neighbour"), find(null, Set.of()));
    assertEquals(List.of("neighbour"), find(Boolean.TRUE, Set.of()));
    assertEquals(List.of("far"), find(Boolean.FALSE, Set.of()));
    assertEquals(List.of("neighbour"), find(null, Set.of("robot2", "robot3")));
    assertEquals(List.of(), find(Boolean.FALSE, Set.of("robot2")));
  }
}
