package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Containers without a direct link reach each other through those that have one. */
class ForwardingTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final List<TRADEContainer> containers = new ArrayList<>();

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
  }

  private TRADEContainer container(String name, String... connectTo) {
    TRADEContainer c = Hubs.hubBuilder(name)
        .property("CONNECTCONTAINERS", String.join(",", connectTo)).build();
    containers.add(c);
    return c;
  }

  private static String address(TRADEContainer c) {
    return c.getServerAddresses().get(0);
  }

  private static TRADEServiceInfo find(TRADEContainer from, String group) {
    TRADEServiceConstraints c = new TRADEServiceConstraints().inGroups(group).name("whoAmI");
    Await.until(WAIT, () -> !from.getAvailableServices(c).isEmpty(), group + " seen from " + from.getName());
    try {
      return from.getAvailableService(c);
    } catch (TRADEException e) {
      throw new AssertionError(e);
    }
  }

  @Test
  void chainForwardsCallsAndRegistryUpdatesBothWays() throws TRADEException {
    TRADEContainer a = container("A");
    TRADEContainer b = container("B", address(a));
    TRADEContainer c = container("C", address(b));
    a.registerAllServices(new Named("A"), "gA");
    c.registerAllServices(new Named("C"), "gC");

    assertEquals("A answers C", find(c, "gA").call(String.class, "C"));
    assertEquals("C answers A", find(a, "gC").call(String.class, "A"));
    assertEquals(2, find(c, "gA").getDistance());
    assertEquals(1, find(b, "gA").getDistance());
    assertEquals(0, find(a, "gA").getDistance());

    // An update made after the fact travels the chain too, and so does its removal.
    Named late = new Named("C2");
    c.registerAllServices(late, "late");
    assertEquals("C2 answers A", find(a, "late").call(String.class, "A"));
    c.deregister(late);
    Await.until(WAIT, () -> a.getAvailableServices(new TRADEServiceConstraints().inGroups("late"))
        .isEmpty(), "deregistration to cross the chain");
    assertTrue(b.getAvailableServices(new TRADEServiceConstraints().inGroups("late")).isEmpty());
  }

  @Test
  void whenTheMiddleLeavesTrafficTakesAnotherPathOrFailsFast() throws TRADEException {
    TRADEContainer a = container("A");
    TRADEContainer b = container("B", address(a));
    TRADEContainer c = container("C", address(b));
    a.registerAllServices(new Named("A"), "gA");
    TRADEServiceInfo fromC = find(c, "gA");
    assertEquals("A answers C", fromC.call(String.class, "C"));

    // A second path A - D - C, then the first middle goes away.
    TRADEContainer d = container("D", address(a), address(c));
    Await.until(WAIT, () -> c.getNeighbours().contains(d.getId())
        && a.getNeighbours().contains(d.getId()), "D to link to A and C");
    b.close();
    containers.remove(b);
    // A call that was in flight on the lost link may fail (typed); the next ones go through D.
    Await.until(WAIT, () -> {
      try {
        return fromC.call(String.class, "C").equals("A answers C");
      } catch (TRADEServiceUnavailableException inFlight) {
        return false;
      } catch (TRADEException e) {
        throw new AssertionError(e);
      }
    }, "calls from C to A to go through D");
    find(c, "gA");

    // With no path left, A's services leave C and calls fail at once.
    d.close();
    containers.remove(d);
    Await.until(WAIT, () -> c.getAvailableServices(new TRADEServiceConstraints().inGroups("gA"))
        .isEmpty(), "A's services to leave C");
    TRADEServiceUnavailableException e = assertThrows(TRADEServiceUnavailableException.class,
        () -> fromC.call(String.class, "C"));
    assertTrue(e.getMessage().startsWith("Service not available any longer"), e.getMessage());
  }
}
