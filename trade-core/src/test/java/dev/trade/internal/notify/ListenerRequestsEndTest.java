package dev.trade.internal.notify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.container.ContainerCore;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.lang.reflect.Field;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A container forgets the listener-form requests it made once their notifications end, whatever
 * ends them (the last delivery, a service leaving, the container that ran them leaving, the
 * listener leaving), and releases the listeners it registered for them: the table does not grow.
 */
class ListenerRequestsEndTest {
  private static final Duration WAIT = Duration.ofSeconds(30);
  @RegisterExtension final Hubs net = new Hubs();

  /** Callbacks and values. */
  public static final class Counter {
    final AtomicInteger calls = new AtomicInteger();

    @TRADEService
    public void tick() {
      calls.incrementAndGet();
    }

    @TRADEService
    public void value(Integer v) {
      calls.incrementAndGet();
    }

    @TRADEService
    public void joined(TRADEServiceInfo info) {}
  }

  /** A service and conditions. */
  public static final class Source {
    @TRADEService
    public int level() {
      return 7;
    }

    @TRADEService
    public boolean yes() {
      return true;
    }

    @TRADEService
    public boolean no() {
      return false;
    }
  }

  /** The container's requester side, which the public API does not show. */
  private static NotificationClient client(TRADEContainer c) throws ReflectiveOperationException {
    Field core = TRADEContainer.class.getDeclaredField("core");
    core.setAccessible(true);
    return ((ContainerCore) core.get(c)).notifications();
  }

  private static TRADEServiceInfo service(TRADEContainer from, String name, String of) {
    return find(from, new TRADEServiceConstraints().name(name), of);
  }

  private static TRADEServiceInfo find(TRADEContainer from, TRADEServiceConstraints c, String of) {
    String name = c.toString();
    Await.until(WAIT, () -> from.getAvailableServices(c).stream()
        .anyMatch(s -> s.getContainerName().equals(of)), name + " of " + of);
    return from.getAvailableServices(c).stream().filter(s -> s.getContainerName().equals(of))
        .findFirst().get();
  }

  private static boolean registered(TRADEContainer c, String name) {
    return !c.getAvailableServices(new TRADEServiceConstraints().name(name)).isEmpty();
  }

  @Test
  void manyNotificationsThatEndedLeaveNothingRemembered() throws Exception {
    TRADEContainer c = net.hub("many");
    c.registerAllServices(new Source());
    NotificationClient client = client(c);
    Counter counter = new Counter();
    TRADEServiceInfo level = service(c, "level", "many");
    int rounds = 200;
    for (int i = 0; i < rounds; i++) {
      c.requestNotification(counter, "once", null, List.of(level), "value");
      c.requestNotification(counter, "after", 1L, List.of(), "tick");
      c.requestNotification(counter, "when", 1L, List.of(service(c, "yes", "many")), "tick");
      c.requestNotification(counter, "if", 1L, List.of(service(c, "no", "many")), "tick");
      if (i % 50 == 0) {
        int limit = 4 * 50 + 4;
        Await.until(WAIT, () -> client.remembered() <= limit, "at most the last rounds remembered");
      }
    }
    Await.until(WAIT, () -> counter.calls.get() == 3 * rounds, "every callback called");
    Await.until(WAIT, () -> client.remembered() == 0, "every ended request forgotten");
    Await.until(WAIT, () -> !registered(c, "tick"), "the listener registered for them released");
  }

  /** A hub whose listener streams a level of a sensor container; returns the hub's client. */
  private NotificationClient streaming(TRADEContainer hub, TRADEContainer sensor, Source source)
      throws Exception {
    sensor.registerAllServices(source);
    hub.requestNotification(new Counter(), "every", 10L, List.of(service(hub, "level", "sensor")),
        "value");
    NotificationClient client = client(hub);
    assertEquals(1, client.remembered());
    return client;
  }

  @Test
  void aServiceThatLeftEndsItsRequestsAndTheirContainerForgetsThem() throws Exception {
    TRADEContainer hub = net.hub("hub");
    TRADEContainer sensor = net.spoke("sensor", hub);
    Source source = new Source();
    NotificationClient client = streaming(hub, sensor, source);
    sensor.deregister(source);
    Await.until(WAIT, () -> client.remembered() == 0, "the request forgotten");
    Await.until(WAIT, () -> !registered(hub, "value"), "the listener released");
  }

  @Test
  void theContainerThatRanThemLeavingEndsThem() throws Exception {
    TRADEContainer hub = net.hub("hub");
    TRADEContainer sensor = net.spoke("sensor", hub);
    NotificationClient client = streaming(hub, sensor, new Source());
    sensor.close();
    Await.until(WAIT, () -> !registered(hub, "level"), "the sensor gone");
    // The next operation of the requester forgets what ran there.
    hub.cancelNotification(new Counter(), "every", null);
    assertEquals(0, client.remembered());
    assertEquals(false, registered(hub, "value"), "the listener released");
  }

  @Test
  void theListenerLeavingEndsItsRequests() throws Exception {
    TRADEContainer c = net.hub("self");
    Counter counter = new Counter();
    c.registerAllServices(counter);
    c.requestNotification(counter, "every", 10L, List.of(), "tick");
    c.requestNotification(counter, "joined", null, null, "joined");
    NotificationClient client = client(c);
    assertEquals(2, client.remembered());
    c.deregister(counter);
    Await.until(WAIT, () -> client.remembered() == 0, "its requests forgotten");
  }

  /** The system service {@code name} of container {@code of}, as {@code from} finds it. */
  private static TRADEServiceInfo system(TRADEContainer from, String name, String of) {
    return find(from, new TRADEServiceConstraints().name(name).inGroups("trade.system"), of);
  }

  /**
   * Only the container that ran a notification may tell its requester that it ended: a third
   * container saying so of someone else's notification is refused, and the requester forgets
   * nothing.
   */
  @Test
  void aThirdContainerCannotEndSomeoneElsesRequest() throws Exception {
    TRADEContainer hub = net.hub("hub");
    TRADEContainer sensor = net.spoke("sensor", hub);
    TRADEContainer intruder = net.spoke("intruder", hub);
    NotificationClient client = streaming(hub, sensor, new Source());
    @SuppressWarnings("unchecked")
    List<java.util.Map<String, Object>> live = system(intruder, "listNotifications", "sensor")
        .call(List.class);
    String id = (String) live.get(0).get("id");
    TRADEServiceInfo ended = system(intruder, "notificationEnded", "hub");
    // What a service throws reaches its caller as the cause of a TRADEInvocationException.
    Throwable e = assertThrows(TRADEInvocationException.class,
        () -> ended.call(Object.class, id, "cancelled")).getCause();
    assertInstanceOf(TRADENotAuthorizedException.class, e);
    assertTrue(e.getMessage().contains("only the container that ran the notification"),
        e.getMessage());
    assertTrue(e.getMessage().contains(sensor.getId()), e.getMessage());
    assertTrue(e.getMessage().contains(intruder.getId()), e.getMessage());
    assertInstanceOf(TRADENotAuthorizedException.class, assertThrows(TRADEInvocationException.class,
        () -> ended.call(Object.class, "no-colon", "x")).getCause());
    assertEquals(1, client.remembered(), "nothing forgotten");
    assertTrue(registered(hub, "value"), "the listener kept");
    // The container that ran it still may.
    assertTrue(hub.cancelNotification(id));
    Await.until(WAIT, () -> client.remembered() == 0, "forgotten once its runner says it ended");
  }
}
