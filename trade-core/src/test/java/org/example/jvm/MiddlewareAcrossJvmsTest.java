package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.discovery.LoopbackMulticast;
import dev.trade.testing.Await;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The middleware's operations across three JVMs, as an administrator and as others: this JVM
 * ("console") links to "robot"; it turns on robot's discovery and "camera", which announces
 * itself, appears; the graph seen from three places agrees; a non-admin is refused and robot
 * audits it; groups change in robot and lookups here follow; a provider is started in robot by
 * class name (and refused for a class not allowed); the admin shuts camera down.
 */
class MiddlewareAcrossJvmsTest {
  private static final Duration START = Duration.ofSeconds(30);
  private static final Duration WAIT = Duration.ofSeconds(20);
  private static final String ADMIN = "alice:alice-secret-1";
  private static final String OPERATOR = "bob:bob-secret-22";

  @TempDir Path dir;

  @Test
  void anAdministratorActsOnOtherJvmsAndOthersAreRefused() throws Exception {
    LoopbackMulticast.assumeUsable();
    Path access = dir.resolve("principals");
    Files.writeString(access, "principal alice admin alice-secret-1\n"
        + "principal bob operator bob-secret-22\n");
    String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
    String[] common = {"PRINCIPALSFILE=" + access, "BROADCASTPORT=" + port,
        "TRADESYSID=jvm-admin", "FAILURETIMEOUT=60000"};
    try (TRADEContainer console = TRADEContainer.builder().name("console")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0")
        .property("PRINCIPALSFILE", access.toString()).property("TRADESYSID", "jvm-admin")
        .build()) {
      String hub = "CONNECTCONTAINERS=" + console.getServerAddresses().get(0);
      try (JvmProcess robot = JvmProcess.start(AdminNodeMain.class, List.of(), with(common,
              "robot", hub, "PROVIDERCLASSES=" + AdminNodeMain.Echo.class.getName()));
          JvmProcess camera = JvmProcess.start(AdminNodeMain.class, List.of(), with(common,
              "camera", "STARTBROADCAST=true"))) {
        robot.awaitLine("READY ", START);
        camera.awaitLine("READY ", START);

        // Discovery turned on in robot by the console: camera appears here.
        TRADEServiceInfo discovery = system(console, "setDiscovery", "robot");
        assertThrows(TRADENotAuthorizedException.class, () -> discovery.call(void.class, true));
        robot.awaitLine("AUDIT refused: setDiscovery(boolean) of container robot called by"
            + " container " + console.getId() + " as anonymous: needs role admin", WAIT);
        TRADENotAuthorizedException operator = assertThrows(TRADENotAuthorizedException.class,
            () -> console.callAs(OPERATOR, discovery, void.class, true));
        assertTrue(operator.getMessage().endsWith("needs role admin, and principal 'bob' has the"
            + " roles operator"), operator.getMessage());
        robot.awaitLine("AUDIT refused: setDiscovery(boolean) of container robot called by"
            + " container " + console.getId() + " as bob: needs role admin", WAIT);
        console.callAs(ADMIN, discovery, void.class, true);
        system(console, "neighbours", "camera");

        // One graph, from three places.
        Map<String, Collection<String>> expected = Map.of("console", List.of("robot"),
            "robot", List.of("camera", "console"), "camera", List.of("robot"));
        Await.until(WAIT, () -> expected.equals(graph(console)), "the graph from console");
        for (String node : List.of("robot", "camera")) {
          TRADEServiceInfo graphAs = only(console, new TRADEServiceConstraints().name("graphAs")
              .inGroups("node-" + node));
          Await.until(WAIT, () -> expected.equals(call(graphAs)), "the graph from " + node);
        }

        // Groups change in robot, through TRADE's signature from a container whose own principal
        // is the admin; lookups in this JVM follow. Without that principal it is refused.
        TRADEServiceInfo graphAs = only(console, new TRADEServiceConstraints().name("graphAs")
            .inGroups("node-robot"));
        assertThrows(TRADENotAuthorizedException.class, () -> console.setServiceGroups(graphAs,
            List.of("moved")));
        try (TRADEContainer desk = TRADEContainer.builder().name("desk")
            .property("CONNECTCONTAINERS", console.getServerAddresses().get(0))
            .property("TRADESYSID", "jvm-admin").property("PRINCIPAL", ADMIN)
            .property("PRINCIPALSFILE", access.toString()).build()) {
          TRADEServiceInfo seenFromDesk = only(desk, new TRADEServiceConstraints()
              .name("graphAs").inGroups("node-robot"));
          desk.setServiceGroups(seenFromDesk, List.of("moved"));
          Await.until(WAIT, () -> console.getAvailableServices(new TRADEServiceConstraints()
              .name("graphAs").inGroups("moved")).size() == 1 && console.getAvailableServices(
              new TRADEServiceConstraints().name("graphAs").inGroups("node-robot")).isEmpty(),
              "graphAs moved, seen here");
          assertEquals(expected.get("robot"), ((Map<?, ?>) graphAs.call(Map.class, ADMIN))
              .get("robot"), "the handle from before the change still calls it");
        }

        // A provider started in robot by class name, and refused when not allowed.
        TRADEServiceInfo start = system(console, "startProvider", "robot");
        assertThrows(TRADENotAuthorizedException.class, () -> start.call(List.class,
            AdminNodeMain.Echo.class.getName(), List.of("started")));
        assertEquals(List.of("upper(java.lang.String)"), console.callAs(ADMIN, start, List.class,
            AdminNodeMain.Echo.class.getName(), List.of("started")));
        TRADEServiceInfo upper = only(console, new TRADEServiceConstraints().name("upper")
            .inGroups("started"));
        assertEquals("robot", upper.getContainerName());
        assertEquals("ABC", upper.call(String.class, "abc"));
        TRADERegistrationException refused = assertThrows(TRADERegistrationException.class,
            () -> console.callAs(ADMIN, start, List.class, "java.util.ArrayList", List.of()));
        assertTrue(refused.getMessage().contains("is not allowed in container robot"),
            refused.getMessage());

        // The admin shuts camera down; a non-admin could not.
        TRADEServiceInfo shutdown = system(console, "shutdown", "camera");
        assertThrows(TRADENotAuthorizedException.class,
            () -> console.callAs(OPERATOR, shutdown, void.class));
        console.callAs(ADMIN, shutdown, void.class);
        Await.until(WAIT, () -> console.getAvailableServices(new TRADEServiceConstraints()
            .inGroups("node-camera")).isEmpty(), "camera's services left");
        Await.until(WAIT, () -> Map.of("console", List.of("robot"), "robot", List.of("console"))
            .equals(graph(console)), "camera left the graph");
      }
    }
  }

  private static String[] with(String[] common, String... more) {
    String[] all = new String[more.length + common.length];
    System.arraycopy(more, 0, all, 0, more.length);
    System.arraycopy(common, 0, all, more.length, common.length);
    return all;
  }

  private static TRADEServiceInfo system(TRADEContainer c, String name, String of) {
    TRADEServiceConstraints sys = new TRADEServiceConstraints().inGroups("trade.system").name(name);
    Await.until(START, () -> c.getAvailableServices(sys).stream()
        .anyMatch(s -> s.getContainerName().equals(of)), name + " of " + of);
    return c.getAvailableServices(sys).stream().filter(s -> s.getContainerName().equals(of))
        .findFirst().get();
  }

  private static TRADEServiceInfo only(TRADEContainer c, TRADEServiceConstraints constraints) {
    Await.until(START, () -> c.getAvailableServices(constraints).size() == 1,
        constraints.toString());
    return c.getAvailableServices(constraints).iterator().next();
  }

  private static Map<String, Collection<String>> graph(TRADEContainer c) {
    try {
      return c.getTRADEContainerGraph(ADMIN);
    } catch (TRADEException e) {
      return Map.of();
    }
  }

  private static Object call(TRADEServiceInfo graphAs) {
    try {
      return graphAs.call(Map.class, ADMIN);
    } catch (TRADEException e) {
      return Map.of();
    }
  }
}
