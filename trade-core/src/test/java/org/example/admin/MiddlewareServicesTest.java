package org.example.admin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * Containers acting on each other through their middleware services, over loopback: refused
 * without the admin role, done with it; groups that change everywhere; providers started by class
 * name; a remote shutdown; one container graph seen from three places.
 */
class MiddlewareServicesTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  static final String ADMIN = "alice:alice-secret-1";
  static final String OPERATOR = "bob:bob-secret-22";

  @RegisterExtension final Hubs net = new Hubs();
  @TempDir Path dir;

  public static final class Arm {
    @TRADEService
    public String wave() {
      return "waved";
    }
  }

  public static final class Gripper {
    @TRADEService
    public String grip() {
      return "gripped";
    }

    @TRADEService
    public String slip() {
      throw new IllegalStateException("slipped");
    }
  }

  private Path accessFile() throws Exception {
    Path f = dir.resolve("principals");
    Files.writeString(f, "principal alice admin alice-secret-1\nprincipal bob operator bob-secret-22\n");
    return f;
  }

  private TRADEContainer hub(String name) throws Exception {
    return net.keep(Hubs.hubBuilder(name).property("PRINCIPALSFILE", accessFile().toString())
        .property("PROVIDERCLASSES", Arm.class.getName()).build());
  }

  private TRADEContainer spoke(String name, TRADEContainer hub) throws Exception {
    return net.keep(Hubs.spokeBuilder(name, hub).property("PRINCIPALSFILE", accessFile().toString())
        .build());
  }

  static TRADEServiceInfo system(TRADEContainer from, String name, String of) {
    TRADEServiceConstraints c = new TRADEServiceConstraints().inGroups("trade.system").name(name);
    Await.until(WAIT, () -> from.getAvailableServices(c).stream()
        .anyMatch(s -> s.getContainerName().equals(of)), name + " of " + of);
    return from.getAvailableServices(c).stream().filter(s -> s.getContainerName().equals(of))
        .findFirst().get();
  }

  @Test
  void onlyAnAdminActsOnAnotherContainer() throws Exception {
    TRADEContainer robot = hub("robot");
    TRADEContainer laptop = spoke("laptop", robot);
    TRADEServiceInfo listen = system(laptop, "startListenForConnections", "robot");

    TRADENotAuthorizedException anonymous = assertThrows(TRADENotAuthorizedException.class,
        () -> listen.call(String.class, "127.0.0.1", 0));
    assertEquals("Not authorized: startListenForConnections(java.lang.String,int) of container"
        + " robot needs role admin, and the call proves no principal (pass credentials"
        + " <principal>:<secret>, or set PRINCIPAL)", anonymous.getMessage());
    TRADENotAuthorizedException operator = assertThrows(TRADENotAuthorizedException.class,
        () -> laptop.callAs(OPERATOR, listen, String.class, "127.0.0.1", 0));
    assertTrue(operator.getMessage().endsWith("needs role admin, and principal 'bob' has the"
        + " roles operator"), operator.getMessage());
    TRADENotAuthorizedException guessed = assertThrows(TRADENotAuthorizedException.class,
        () -> laptop.callAs("alice:not-the-secret", listen, String.class, "127.0.0.1", 0));
    assertFalse(guessed.getMessage().contains("alice-secret-1"));
    assertEquals(1, robot.getServerAddresses().size());

    String bound = laptop.callAs(ADMIN, listen, String.class, "127.0.0.1", 0);
    assertEquals(2, robot.getServerAddresses().size());
    assertTrue(robot.getServerAddresses().contains(bound), bound);

    // Ordinary services stay open to anyone.
    robot.registerAllServices(new Arm(), "arm");
    TRADEServiceInfo wave = first(laptop, new TRADEServiceConstraints().name("wave"));
    assertEquals("waved", wave.call(String.class));
  }

  @Test
  void theStaticFormsActOnTheirOwnContainerWithCredentials() throws Exception {
    TRADEContainer robot = hub("robot");
    assertThrows(TRADENotAuthorizedException.class, () -> robot.stopListenForConnections("diarcUser"));
    robot.stopListenForConnections(ADMIN);
    assertEquals(List.of(), robot.getServerAddresses());
    robot.startListenForConnections(ADMIN, "127.0.0.1", 0);
    assertEquals(1, robot.getServerAddresses().size());
    robot.registerAllServices(new Arm(), "arm");
    robot.reset(ADMIN);
    assertEquals(List.of(), List.copyOf(robot.getAvailableServices(
        new TRADEServiceConstraints().name("wave"))));
    assertEquals(1, robot.getAvailableServices(new TRADEServiceConstraints()
        .inGroups("trade.system").name("shutdown")).size(), "system services stay");
  }

  @Test
  void groupsOfAServiceChangeAndLookupsElsewhereFollow() throws Exception {
    TRADEContainer robot = hub("robot");
    TRADEContainer laptop = spoke("laptop", robot);
    TRADEServiceInfo wave = robot.registerAllServices(new Arm(), "arm").iterator().next();
    TRADEServiceConstraints inArm = new TRADEServiceConstraints().name("wave").inGroups("arm");
    TRADEServiceConstraints inHead = new TRADEServiceConstraints().name("wave").inGroups("head");
    Await.until(WAIT, () -> laptop.getAvailableServices(inArm).size() == 1, "wave in arm");

    robot.setServiceGroups(wave, List.of("head"));
    Await.until(WAIT, () -> laptop.getAvailableServices(inHead).size() == 1
        && laptop.getAvailableServices(inArm).isEmpty(), "wave moved to head, seen remotely");
    assertEquals(List.of("head"), List.copyOf(robot.getAvailableService(inHead).getGroups()));
    assertEquals("waved", wave.call(String.class), "the old handle still calls the service");

    robot.addServiceGroups(wave, List.of("arm"));
    Await.until(WAIT, () -> laptop.getAvailableServices(inArm).size() == 1
        && laptop.getAvailableServices(inHead).size() == 1, "in both");
    robot.resetServiceGroups(wave);
    Await.until(WAIT, () -> laptop.getAvailableServices(inArm).isEmpty()
        && laptop.getAvailableServices(inHead).isEmpty(), "in none");
    assertThrows(TRADERegistrationException.class,
        () -> robot.setServiceGroups(wave, List.of("trade.system")));
  }

  @Test
  void aProviderIsStartedByClassNameOnlyWhenAllowed() throws Exception {
    TRADEContainer robot = hub("robot");
    TRADEContainer laptop = spoke("laptop", robot);
    TRADEServiceInfo start = system(laptop, "startProvider", "robot");
    @SuppressWarnings("unchecked")
    List<String> started = laptop.callAs(ADMIN, start, List.class, Arm.class.getName(),
        List.of("arm"));
    assertEquals(List.of("wave()"), started);
    TRADEServiceInfo wave = first(laptop, new TRADEServiceConstraints().name("wave").inGroups("arm"));
    assertEquals("robot", wave.getContainerName());

    TRADERegistrationException refused = assertThrows(TRADERegistrationException.class,
        () -> laptop.callAs(ADMIN, start, List.class, "java.lang.Object", List.of()));
    assertEquals("startProvider: class java.lang.Object is not allowed in container robot; add it"
        + " (or its package, pkg.*) to that container's PROVIDERCLASSES", refused.getMessage());
    assertEquals(1, laptop.callAs(ADMIN, system(laptop, "stopProvider", "robot"), int.class,
        Arm.class.getName()));
    Await.until(WAIT, () -> laptop.getAvailableServices(new TRADEServiceConstraints()
        .name("wave")).isEmpty(), "wave stopped");
  }

  @Test
  void theGraphSeenFromThreePlacesAgreesAndAnAdminShutsAContainerDown() throws Exception {
    TRADEContainer hub = hub("hub");
    TRADEContainer a = spoke("a", hub);
    TRADEContainer b = spoke("b", hub);
    Map<String, Collection<String>> expected = Map.of("hub", List.of("a", "b"), "a",
        List.of("hub"), "b", List.of("hub"));
    for (TRADEContainer c : List.of(hub, a, b)) {
      Await.until(WAIT, () -> expected.equals(graph(c)), "the graph from " + c.getName());
    }
    assertThrows(TRADENotAuthorizedException.class, () -> a.getTRADEContainerGraph("nobody"));

    TRADEServiceInfo shutdown = system(a, "shutdown", "b");
    assertThrows(TRADENotAuthorizedException.class, () -> shutdown.call(void.class));
    assertThrows(TRADENotAuthorizedException.class,
        () -> a.callAs(OPERATOR, shutdown, void.class));
    a.callAs(ADMIN, shutdown, void.class);
    Await.until(WAIT, () -> closed(b), "b closed");
    Map<String, Collection<String>> after = Map.of("hub", List.of("a"), "a", List.of("hub"));
    Await.until(WAIT, () -> after.equals(graph(a)), "b left the graph");
  }

  @Test
  void aContainersDescriptionCarriesItsCallStatisticsAndItsLinksRoundTrips() throws Exception {
    TRADEContainer robot = hub("robot");
    TRADEContainer laptop = spoke("laptop", robot);
    robot.registerAllServices(new Gripper(), "arm");
    TRADEServiceInfo describe = system(laptop, "describeContainer", "robot");
    assertEquals(List.of(), describeAs(laptop, describe).get("statistics"),
        "no statistics before they are switched on");

    system(laptop, "setCallStatistics", "robot").call(void.class, true);
    TRADEServiceInfo grip = first(laptop, new TRADEServiceConstraints().name("grip"));
    TRADEServiceInfo slip = first(laptop, new TRADEServiceConstraints().name("slip"));
    for (int i = 0; i < 3; i++) {
      assertEquals("gripped", grip.call(String.class));
    }
    assertThrows(TRADEException.class, () -> slip.call(String.class));

    Map<String, Object> robotSays = describeAs(laptop, describe);
    Map<String, Object> gripStats = statisticsOf(robotSays, "grip()");
    assertEquals(3L, gripStats.get("calls"), gripStats.toString());
    assertEquals(0L, gripStats.get("failures"), gripStats.toString());
    assertTrue((Double) gripStats.get("p50Micros") > 0, gripStats.toString());
    assertTrue((Double) gripStats.get("p99Micros") >= (Double) gripStats.get("p50Micros"),
        gripStats.toString());
    Map<String, Object> slipStats = statisticsOf(robotSays, "slip()");
    assertEquals(1L, slipStats.get("calls"), slipStats.toString());
    assertEquals(1L, slipStats.get("failures"), slipStats.toString());

    // The first probe goes out as the link comes up; its echo comes within the link's first
    // round trip.
    String laptopId = (String) describeAs(laptop, system(laptop, "describeContainer", "laptop"))
        .get("id");
    Await.until(WAIT, () -> roundTripsOf(describeAs(laptop, describe)).containsKey(laptopId),
        "robot's round trip to laptop, in its description");
    Map<String, Object> rtt = roundTripsOf(describeAs(laptop, describe));
    assertEquals(List.of(laptopId), List.copyOf(rtt.keySet()), rtt.toString());
    assertTrue((Double) rtt.get(laptopId) > 0, rtt.toString());

    Await.until(WAIT, () -> roundTrips(laptop).keySet().equals(java.util.Set.of("robot",
        "laptop")) && roundTrips(laptop).values().stream().allMatch(m -> m.size() == 1),
        "the graph with round trips, from laptop: " + roundTrips(laptop));
    Map<String, Map<String, Double>> graph = laptop.getContainerRoundTrips(ADMIN);
    assertTrue(graph.get("robot").get("laptop") > 0, graph.toString());
    assertTrue(graph.get("laptop").get("robot") > 0, graph.toString());
    assertThrows(TRADENotAuthorizedException.class, () -> laptop.getContainerRoundTrips(OPERATOR));
  }

  @SuppressWarnings("unchecked")
  private static Map<String, Object> describeAs(TRADEContainer from, TRADEServiceInfo describe) {
    try {
      return from.callAs(ADMIN, describe, Map.class);
    } catch (TRADEException e) {
      throw new AssertionError("describeContainer as an admin failed", e);
    }
  }

  @SuppressWarnings("unchecked")
  private static Map<String, Object> statisticsOf(Map<String, Object> description,
      String service) {
    for (Map<String, Object> m : (List<Map<String, Object>>) description.get("statistics")) {
      if (m.get("service").equals(service)) {
        return m;
      }
    }
    throw new AssertionError("no statistics of " + service + " in " + description);
  }

  @SuppressWarnings("unchecked")
  private static Map<String, Object> roundTripsOf(Map<String, Object> description) {
    return (Map<String, Object>) description.get("roundTripMicros");
  }

  private static Map<String, Map<String, Double>> roundTrips(TRADEContainer c) {
    try {
      return c.getContainerRoundTrips(ADMIN);
    } catch (TRADEException e) {
      return Map.of();
    }
  }

  private static TRADEServiceInfo first(TRADEContainer c, TRADEServiceConstraints constraints) {
    Await.until(WAIT, () -> !c.getAvailableServices(constraints).isEmpty(), constraints.toString());
    return c.getAvailableServices(constraints).iterator().next();
  }

  private static boolean closed(TRADEContainer c) {
    try {
      c.getAvailableServices();
      return false;
    } catch (IllegalStateException e) {
      return true;
    }
  }

  private static Map<String, Collection<String>> graph(TRADEContainer c) {
    try {
      return c.getTRADEContainerGraph(ADMIN);
    } catch (TRADEException e) {
      return Map.of();
    }
  }
}
