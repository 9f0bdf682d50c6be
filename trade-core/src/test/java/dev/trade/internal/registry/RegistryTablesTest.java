package dev.trade.internal.registry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** Other containers' tables applied together: one snapshot, one call of the listeners. */
class RegistryTablesTest {
  private final Registry registry = new Registry("self", "self", "host");
  private final List<List<Entry>> calls = new ArrayList<>();

  RegistryTablesTest() {
    registry.addListener((added, removed) -> calls.add(added));
  }

  private static Table table(String owner, long version, String... services) {
    List<ServiceDescriptor> list = new ArrayList<>();
    long id = 1;
    for (String name : services) {
      list.add(new ServiceDescriptor(owner, owner, "host", id++, name, List.of(), List.of(), "int",
          Set.of(), List.of()));
    }
    return new Table(owner, version, list);
  }

  private List<Entry> named(String name) {
    return registry.all().stream().filter(e -> e.descriptor().name().equals(name)).toList();
  }

  @Test
  void manyTablesAreListedWithOneCallOfTheListeners() {
    assertTrue(registry.applyTables(List.of(table("a", 1, "x"), table("b", 1, "x", "y"),
        table("c", 1)), Map.of("a", 1, "b", 2, "c", 3)));
    assertEquals(1, calls.size(), "one change for all three tables");
    assertEquals(3, calls.get(0).size(), "with every service added");
    assertEquals(3, registry.all().size());
    assertEquals(List.of(2), named("y").stream().map(Entry::distance).toList());
  }

  @Test
  void staleTablesAreLeftOutAndAllStaleChangesNothing() {
    registry.applyTables(List.of(table("a", 2, "x")), Map.of("a", 1));
    calls.clear();
    assertFalse(registry.applyTables(List.of(table("a", 2, "y"), table("self", 9, "z")),
        Map.of("a", 1, "self", 0)), "a version known already, and this container's own");
    assertTrue(calls.isEmpty());
    assertTrue(registry.applyTables(List.of(table("a", 1, "old"), table("b", 1, "new")),
        Map.of("a", 1, "b", 1)));
    assertEquals(List.of("new"), calls.get(0).stream().map(e -> e.descriptor().name()).toList());
    assertEquals(1, named("x").size(), "a's table of version 2 stays");
    assertTrue(named("old").isEmpty());
  }

  @Test
  void routesAreFollowedWithOneChangeForMovesAndNewTables() {
    registry.applyTables(List.of(table("a", 1, "x"), table("b", 1, "x")), Map.of("a", 3, "b", 1));
    assertEquals(List.of("b", "a"), owners(named("x")), "nearest first");
    calls.clear();

    registry.followRoutes(Map.of("a", 1, "b", 2, "unknown", 1), List.of(table("c", 1, "x")),
        Map.of("c", 2));
    assertEquals(1, calls.size(), "one change for the moves and the new table");
    assertEquals(List.of("c"), owners(calls.get(0)), "only the new table's services are added");
    assertEquals(List.of("a", "b", "c"), owners(named("x")), "a moved nearer, b farther");
    assertEquals(List.of(1, 2, 2), named("x").stream().map(Entry::distance).toList());

    registry.followRoutes(Map.of("c", 1), List.of(), Map.of());
    assertEquals(1, calls.size(), "a move alone is no change for the listeners");
    assertEquals(List.of("a", "c", "b"), owners(named("x")), "but lookups see it");
  }

  private static List<String> owners(List<Entry> entries) {
    return entries.stream().map(e -> e.descriptor().containerId()).toList();
  }
}
