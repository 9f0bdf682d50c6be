package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Containers that find each other by multicast on loopback (range localhost: interface lo, TTL 0,
 * nothing leaves the machine), with no addresses configured.
 */
class ContainerDiscoveryTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final List<TRADEContainer> containers = new ArrayList<>();
  private final String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));

  public static class Arm {
    private final String name;

    public Arm(String name) {
      this.name = name;
    }

    @TRADEService
    public String whoAmI() {
      return name;
    }
  }

  public static class Watcher {
    final List<String> joined = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void joined(TRADEServiceInfo info) {
      joined.add(info.getContainerName());
    }
  }

  @BeforeEach
  void multicast() {
    LoopbackMulticast.assumeUsable();
  }

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
  }

  private TRADEContainer container(String name, String system, String credentials) {
    TRADEContainer c = TRADEContainer.builder().name(name)
        .property("STARTDISCOVERY", "true").property("STARTBROADCAST", "true")
        .property("BROADCASTPORT", port).property("TRADESYSID", system)
        .property("CREDENTIALS", credentials).build();
    containers.add(c);
    return c;
  }

  private static void await(BooleanSupplier condition, String what) {
    Await.until(WAIT, condition, what);
  }

  private static List<String> names(TRADEContainer c) {
    List<String> result = new ArrayList<>();
    c.getAvailableServices(new TRADEServiceConstraints().name("whoAmI")).forEach(
        s -> result.add(s.getContainerName()));
    Collections.sort(result);
    return result;
  }

  @Test
  void threeContainersFindEachOtherAndCallAcross() throws TRADEException {
    TRADEContainer a = container("a", "robots", "secret");
    TRADEContainer b = container("b", "robots", "secret");
    TRADEContainer c = container("c", "robots", "secret");
    for (TRADEContainer x : containers) {
      x.registerAllServices(new Arm(x.getName()));
    }
    for (TRADEContainer x : containers) {
      await(() -> names(x).equals(List.of("a", "b", "c")), "all services on " + x.getName());
    }
    assertEquals("a", a.getAvailableService(new TRADEServiceConstraints().name("whoAmI"))
        .getContainerName(), "local first");
    assertEquals(2, a.getAvailableServices(new TRADEServiceConstraints().name("whoAmI")
        .not(new TRADEServiceConstraints().local())).size());
    for (TRADEContainer from : containers) {
      for (TRADEServiceInfo s : from.getAvailableServices(new TRADEServiceConstraints().name("whoAmI"))) {
        assertEquals(s.getContainerName(), s.call(String.class));
      }
    }
    assertTrue(b.isDiscovering() && b.isBroadcasting());
  }

  @Test
  void aLateJoinerFiresJoinedAtTheOthers() throws TRADEException {
    TRADEContainer a = container("a", "robots", "secret");
    Watcher w = new Watcher();
    a.requestNotification(w, "joined", new TRADEServiceConstraints().name("whoAmI"), null, "joined");
    TRADEContainer late = container("late", "robots", "secret");
    late.registerAllServices(new Arm("late"));
    await(() -> w.joined.contains("late"), "joined from the late container");
  }

  @Test
  void otherSystemsAndWrongCredentialsStaySeparateOnTheSameGroupAndPort() throws TRADEException {
    TRADEContainer a1 = container("a1", "alpha", "secret");
    TRADEContainer a2 = container("a2", "alpha", "secret");
    TRADEContainer b1 = container("b1", "beta", "secret");
    TRADEContainer b2 = container("b2", "beta", "secret");
    TRADEContainer intruder = container("intruder", "alpha", "guess");
    for (TRADEContainer x : containers) {
      x.registerAllServices(new Arm(x.getName()));
    }
    await(() -> names(a1).equals(List.of("a1", "a2")), "alpha to form");
    await(() -> names(b1).equals(List.of("b1", "b2")), "beta to form");
    // Both systems formed while the intruder announced all along: it never joined either.
    await(() -> names(a2).equals(List.of("a1", "a2")) && names(b2).equals(List.of("b1", "b2")),
        "both systems complete");
    assertEquals(List.of("intruder"), names(intruder));
    assertTrue(intruder.getNeighbours().isEmpty());
    assertFalse(a1.getNeighbours().contains(intruder.getId()));
  }

  @Test
  void discoveryCanBeSwitchedOnAtRunTime() throws TRADEException {
    TRADEContainer quiet = TRADEContainer.builder().name("quiet").property("BROADCASTPORT", port)
        .property("TRADESYSID", "robots").property("CREDENTIALS", "secret").build();
    containers.add(quiet);
    assertFalse(quiet.isDiscovering());
    TRADEContainer loud = container("loud", "robots", "secret");
    loud.registerAllServices(new Arm("loud"));
    quiet.setDiscovery(true);
    await(() -> names(quiet).equals(List.of("loud")), "the quiet container to find the loud one");
    assertTrue(quiet.isDiscovering());
    assertFalse(quiet.isBroadcasting());
  }
}
