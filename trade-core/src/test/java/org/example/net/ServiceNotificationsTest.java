package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.TRADETimeoutException;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Notifications through the public API, in real time across containers of one JVM: the system
 * services, the paper's example, streaming, non-blocking calls and waiting for a service.
 */
class ServiceNotificationsTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  private static final TRADEServiceConstraints SYSTEM = new TRADEServiceConstraints().inGroups("trade.system");
  private final Containers containers = new Containers();

  /** The paper's battery: a condition, and a level that streams. */
  public static class Battery {
    volatile boolean low;
    final AtomicInteger level = new AtomicInteger(100);

    @TRADEService
    public boolean isLowBattery() {
      return low;
    }

    @TRADEService
    public boolean isOverheated() {
      return false;
    }

    @TRADEService
    public int level() {
      return level.getAndDecrement();
    }

    @TRADEService
    public int add(int a, int b) {
      return a + b;
    }

    @TRADEService
    public int broken() {
      throw new IllegalStateException("no reading");
    }
  }

  /** The paper's dock. */
  public static class Dock {
    final AtomicInteger docked = new AtomicInteger();

    @TRADEService
    public void dock() {
      docked.incrementAndGet();
    }
  }

  /** A listener whose callbacks are services. */
  public static class Listener {
    final List<Object> got = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void value(int v) {
      got.add(v);
    }

    @TRADEService
    public void joined(TRADEServiceInfo info) {
      got.add(info.serviceName);
    }
  }

  @AfterEach
  void close() {
    containers.close();
  }

  private TRADEContainer container(String name, String... settings) {
    return containers.build(name, settings);
  }

  private TRADEContainer hub() {
    return container("hub", "STARTACCEPTINGCONNECTIONS", "true", "SERVERIPS", "127.0.0.1@0");
  }

  private TRADEContainer spoke(String name, TRADEContainer hub) {
    return container(name, "CONNECTCONTAINERS", hub.getServerAddresses().get(0));
  }

  private static TRADEServiceInfo only(TRADEContainer c, String name, String container) {
    for (TRADEServiceInfo s : c.getAvailableServices(new TRADEServiceConstraints().name(name))) {
      if (s.getContainerName().equals(container)) {
        return s;
      }
    }
    throw new AssertionError(name + " of " + container + " not known in " + c.getName());
  }

  private static TRADEServiceInfo await(TRADEContainer c, String name, String container) {
    Await.until(WAIT, () -> c.getAvailableServices(new TRADEServiceConstraints().name(name)).stream()
        .anyMatch(s -> s.getContainerName().equals(container)), name + " of " + container);
    return only(c, name, container);
  }

  /** Container {@code of}'s system service {@code name}, as {@code from} sees it. */
  private static TRADEServiceInfo system(TRADEContainer from, String name, String of) {
    Await.until(WAIT, () -> from.getAvailableServices(SYSTEM).stream()
        .anyMatch(s -> s.serviceName.equals(name) && s.getContainerName().equals(of)), name + " of " + of);
    return from.getAvailableServices(SYSTEM).stream()
        .filter(s -> s.serviceName.equals(name) && s.getContainerName().equals(of)).findFirst().get();
  }

  @SuppressWarnings("unchecked")
  private static List<Map<String, Object>> listOf(TRADEContainer from, String of, String which)
      throws TRADEException {
    return system(from, which, of).call(List.class);
  }

  private static List<Map<String, Object>> listNow(TRADEContainer from, String of, String which) {
    try {
      return listOf(from, of, which);
    } catch (TRADEException e) {
      throw new IllegalStateException(e);
    }
  }

  @Test
  void systemServicesReplicateButOrdinaryLookupsDoNotListThem() throws TRADEException {
    TRADEContainer hub = hub();
    TRADEContainer arm = spoke("arm", hub);
    arm.registerAllServices(new Dock(), "robot");
    await(hub, "dock", "arm");
    assertEquals(List.of("dock"), hub.getAvailableServices().stream().map(s -> s.serviceName).toList());
    assertEquals(List.of(), hub.getAvailableServices(new TRADEServiceConstraints().name("listNotifications")));
    TRADEServiceInfo armList = system(hub, "listNotifications", "arm");
    assertEquals(List.of("trade.system"), List.copyOf(armList.getGroups()));
    assertEquals(List.of(), armList.call(List.class), "arm runs no notification");
  }

  @Test
  void usersCannotRegisterIntoTheReservedGroup() {
    TRADEContainer c = container("reserved");
    TRADERegistrationException e = assertThrows(TRADERegistrationException.class,
        () -> c.registerAllServices(new Dock(), "robot", "trade.system"));
    assertEquals("Group 'trade.system' is reserved for the container's own services (notifications"
        + " and other middleware operations); register in another group", e.getMessage());
    assertEquals(List.of(), c.getAvailableServices());
  }

  /**
   * The paper's example: the planner's container A asks for dock() (in C) when isLowBattery()
   * (in B) becomes true; the notification runs in B, where polling is a local call.
   */
  @Test
  void whenLowBatteryThenDockAcrossThreeContainers() throws TRADEException {
    TRADEContainer a = hub();
    TRADEContainer b = spoke("b", a);
    TRADEContainer c = spoke("c", a);
    Battery battery = new Battery();
    Dock dock = new Dock();
    b.registerAllServices(battery);
    c.registerAllServices(dock);
    TRADEServiceInfo isLow = await(a, "isLowBattery", "b");
    TRADEServiceInfo dockInfo = await(a, "dock", "c");

    String first = a.requestNotification("when", 5L, List.of(isLow), dockInfo);
    assertTrue(first.startsWith(b.getId() + ":"), "runs in b: " + first);
    List<Map<String, Object>> live = listOf(c, "b", "listNotifications");
    assertEquals(1, live.size());
    assertEquals("when", live.get(0).get("type"));
    assertEquals("hub", live.get(0).get("requester"));
    assertEquals(List.of("isLowBattery() @ b"), live.get(0).get("services"));
    assertEquals("dock() @ c", live.get(0).get("callback"));

    battery.low = true;
    Await.until(WAIT, () -> dock.docked.get() == 1, "docked");
    Await.until(WAIT, () -> listNow(a, "b", "listNotifications").isEmpty(), "the when ended");
    assertEquals(1, dock.docked.get(), "docked exactly once");

    // A second one, cancelled by id from the dock's container.
    String second = a.requestNotification("every", 1000L, List.of(), dockInfo);
    assertTrue(c.cancelNotification(second));
    assertFalse(c.cancelNotification(second));
    assertEquals(List.of(), listOf(a, "hub", "listNotifications"));

    // A third, ended when its callback's container goes away.
    String third = a.requestNotification("when", 5L, List.of(only(a, "isOverheated", "b")), dockInfo);
    c.close();
    Await.until(WAIT, () -> listNow(a, "b", "endedNotifications").stream()
        .anyMatch(e -> e.get("id").equals(third)), "the third ended");
    Map<String, Object> ended = listOf(a, "b", "endedNotifications").stream()
        .filter(e -> e.get("id").equals(third)).findFirst().get();
    assertEquals("its callback dock() @ c left", ended.get("endReason"));
  }

  @Test
  void everyWithAServiceStreamsItsResultsToAListenerInAnotherContainer() throws TRADEException {
    TRADEContainer hub = hub();
    TRADEContainer sensor = spoke("sensor", hub);
    sensor.registerAllServices(new Battery());
    TRADEServiceInfo level = await(hub, "level", "sensor");
    Listener listener = new Listener();
    hub.requestNotification(listener, "every", Duration.ofMillis(5), List.of(level), "value");
    Await.until(WAIT, () -> listener.got.size() >= 5, "five values");
    hub.cancelNotification(listener, "every", null);
    List<Object> got = List.copyOf(listener.got);
    assertEquals(List.of(100, 99, 98, 97, 96), got.subList(0, 5));
    assertEquals(List.of(), hub.getAvailableServices(new TRADEServiceConstraints().name("value")),
        "the listener, registered for it, is deregistered");
    assertEquals(List.of(), listOf(hub, "sensor", "listNotifications"));
  }

  @Test
  void onceIsANonBlockingCallWhoseResultReachesTheListener() throws TRADEException {
    TRADEContainer c = container("once");
    c.registerAllServices(new Battery());
    Listener listener = new Listener();
    c.requestNotification(listener, "once", new Object[] {2, 3},
        List.of(c.getAvailableService(new TRADEServiceConstraints().name("add"))), "value");
    Await.until(WAIT, () -> listener.got.equals(List.of(5)), "the sum");
  }

  @Test
  void aBadRequestToAnotherContainerIsRefusedThereWithItsTypedError() throws TRADEException {
    TRADEContainer hub = hub();
    TRADEContainer b = spoke("b", hub);
    b.registerAllServices(new Battery());
    Dock dock = new Dock();
    hub.registerAllServices(dock);
    TRADEServiceInfo isLow = await(hub, "isLowBattery", "b");
    TRADEBadArgumentsException e = assertThrows(TRADEBadArgumentsException.class,
        () -> hub.requestNotification("when", 0L, List.of(isLow), only(hub, "dock", "hub")));
    assertEquals("'when' needs a period of at least 1 ms; got 0 ms", e.getMessage());
    assertEquals(List.of(), listOf(hub, "b", "listNotifications"));
  }

  @Test
  void callAsyncCompletesLocalAndRemoteCallsAndTheirFailures() throws Exception {
    TRADEContainer hub = hub();
    TRADEContainer b = spoke("b", hub);
    b.registerAllServices(new Battery());
    hub.registerAllServices(new Dock());
    TRADEServiceInfo add = await(hub, "add", "b");
    List<CompletableFuture<Integer>> sums = new ArrayList<>();
    for (int i = 0; i < 200; i++) {
      sums.add(add.callAsync(Integer.class, i, 1));
    }
    for (int i = 0; i < 200; i++) {
      assertEquals(i + 1, sums.get(i).get(WAIT.toSeconds(), TimeUnit.SECONDS));
    }
    ExecutionException broken = assertThrows(ExecutionException.class,
        () -> only(hub, "broken", "b").callAsync(int.class).get(WAIT.toSeconds(), TimeUnit.SECONDS));
    assertInstanceOf(TRADEInvocationException.class, broken.getCause());
    assertEquals(null, only(hub, "dock", "hub").callAsync(void.class).get(WAIT.toSeconds(), TimeUnit.SECONDS));
    ExecutionException bad = assertThrows(ExecutionException.class,
        () -> add.callAsync(int.class, 1).get(WAIT.toSeconds(), TimeUnit.SECONDS));
    assertInstanceOf(TRADEBadArgumentsException.class, bad.getCause());
  }

  @Test
  void callAsyncOnAClosedContainerFailsAtOnceAndStartsNoThread() throws Exception {
    TRADEContainer hub = hub();
    TRADEContainer b = spoke("b", hub);
    b.registerAllServices(new Battery());
    hub.registerAllServices(new Dock());
    TRADEServiceInfo add = await(hub, "add", "b");
    TRADEServiceInfo dock = only(hub, "dock", "hub");
    hub.close();
    for (CompletableFuture<?> f : List.of(add.callAsync(Integer.class, 1, 2), dock.callAsync(void.class))) {
      ExecutionException e = assertThrows(ExecutionException.class, () -> f.get(WAIT.toSeconds(),
          TimeUnit.SECONDS));
      // As call() would throw: the service is not reachable from a closed container.
      assertInstanceOf(TRADEServiceUnavailableException.class, e.getCause());
      assertTrue(e.getCause().getMessage().contains("container hub is closed"),
          e.getCause().getMessage());
    }
    assertTrue(Thread.getAllStackTraces().keySet().stream()
        .noneMatch(t -> t.getName().startsWith("trade-async-hub-")), "no pool made after close");
  }

  @Test
  void waitForServiceReturnsOneNowOrTheFirstToJoinOrTimesOut() throws Exception {
    TRADEContainer hub = hub();
    TRADEServiceConstraints docks = new TRADEServiceConstraints().name("dock");
    TRADETimeoutException none = assertThrows(TRADETimeoutException.class,
        () -> hub.waitForService(docks, Duration.ofMillis(50)));
    assertTrue(none.getMessage().startsWith("No service matching "), none.getMessage());
    CompletableFuture<TRADEServiceInfo> waiting = CompletableFuture.supplyAsync(() -> {
      try {
        return hub.waitForService(docks, WAIT);
      } catch (TRADEException e) {
        throw new IllegalStateException(e);
      }
    });
    TRADEContainer c = spoke("c", hub);
    c.registerAllServices(new Dock());
    TRADEServiceInfo found = waiting.get(WAIT.toSeconds() * 2, TimeUnit.SECONDS);
    assertEquals("c", found.getContainerName());
    assertEquals("dock", hub.waitForService(docks, Duration.ofMillis(1)).serviceName, "one is there now");
    assertEquals(List.of("dock"), hub.getAvailableServices().stream().map(s -> s.serviceName).toList(),
        "the waiter is not left registered");
  }

  /**
   * A peer that knows only the wire format asks another container for joined and left with
   * constraints in their neutral form (a map, docs/protocol.md): only matching services are told.
   */
  @Test
  void joinedAndLeftRequestedOverTheWireFilterByConstraintsInTheirNeutralForm() throws Exception {
    TRADEContainer hub = hub();
    TRADEContainer b = spoke("b", hub);
    NotificationsTest.Recorder watcher = new NotificationsTest.Recorder();
    hub.registerAllServices(watcher);
    Map<String, Object> robotDocks = new java.util.LinkedHashMap<>();
    robotDocks.put("name", "dock");
    robotDocks.put("argTypes", List.of());
    robotDocks.put("inGroups", List.of("robot"));
    TRADEServiceInfo request = system(hub, "requestNotification", "b");
    String joined = request.call(String.class, "joined", robotDocks, List.of(),
        only(hub, "joined", "hub"), "hub");
    String left = request.call(String.class, "left", robotDocks, List.of(),
        only(hub, "left", "hub"), "hub");
    assertTrue(joined.startsWith(b.getId() + ":") && left.startsWith(b.getId() + ":"), joined);

    TRADEInvocationException bad = assertThrows(TRADEInvocationException.class,
        () -> request.call(String.class, "joined", Map.of("nmae", "dock"), List.of(),
            only(hub, "joined", "hub"), "hub"));
    assertInstanceOf(TRADEBadArgumentsException.class, bad.getCause());
    assertEquals("Constraints: constraints has an unknown key 'nmae'; the keys are name, argTypes,"
        + " returnType, inGroups, notInGroups, local, host, onLocalhost, notOnHost, not, or",
        bad.getCause().getMessage());
    assertEquals(2, listOf(hub, "b", "listNotifications").size(), "the bad one was not started");

    Dock simDock = new Dock();
    Dock robotDock = new Dock();
    b.registerAllServices(simDock, "sim");
    b.registerAllServices(new Battery(), "robot");
    b.registerAllServices(robotDock, "robot");
    b.deregister(simDock);
    b.deregister(robotDock);
    Await.until(WAIT, () -> watcher.events.size() >= 2, "the robot dock joined and left");
    assertEquals(List.of("joined dock@b", "left dock@b"), List.copyOf(watcher.events),
        "only the matching service (the dock in group sim is another), in order");
  }

  @Test
  void registerNowOrWhenJoinedReturnsTheMatchesNow() throws TRADEException {
    TRADEContainer c = container("now");
    c.registerAllServices(new Dock());
    Listener listener = new Listener();
    Collection<TRADEServiceInfo> now = c.registerNotificationNowOrWhenJoined(listener,
        new TRADEServiceConstraints().name("dock"), "joined");
    assertEquals(List.of("dock"), now.stream().map(s -> s.serviceName).toList());
    Await.until(WAIT, () -> listener.got.equals(List.of("dock")), "the callback for the match now");
  }
}
