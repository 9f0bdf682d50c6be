package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** joined / left notifications, locally and across containers. */
class NotificationsTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final Containers containers = new Containers();

  /** Records what it is told; its callbacks are services, as TRADE requires. */
  public static class Recorder {
    final List<String> events = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void joined(TRADEServiceInfo info) {
      events.add("joined " + info.serviceName + "@" + info.getContainerName());
    }

    @TRADEService
    public void left(TRADEServiceInfo info) {
      events.add("left " + info.serviceName + "@" + info.getContainerName());
    }

    @TRADEService
    public void fails(TRADEServiceInfo info) {
      throw new IllegalStateException("callback failure for " + info.serviceName);
    }

    public void notAService(TRADEServiceInfo info) {}
  }

  public static class Gripper {
    @TRADEService
    public void openGripper(int speed) {}
  }

  public static class Numbered {
    @TRADEService
    public int number() {
      return 0;
    }
  }

  @AfterEach
  void close() {
    containers.close();
  }

  private TRADEContainer container(String name, String... settings) {
    return containers.build(name, settings);
  }

  @Test
  void localRegisterAndDeregisterFireJoinedAndLeftInOrder() throws TRADEException {
    TRADEContainer trade = container("local");
    Recorder r = new Recorder();
    TRADEServiceConstraints grippers = new TRADEServiceConstraints().name("openGripper");
    trade.requestNotification(r, "joined", grippers, null, "joined");
    trade.requestNotification(r, "left", grippers, null, "left");
    Gripper g = new Gripper();
    trade.registerAllServices(g);
    trade.registerAllServices(new Numbered()); // does not match
    trade.deregister(g);
    Await.until(WAIT, () -> r.events.size() >= 2, "two events");
    assertEquals(List.of("joined openGripper@local", "left openGripper@local"), r.events);
  }

  @Test
  void remoteContainersJoiningAndLeavingAreNotified() throws TRADEException {
    TRADEContainer hub = container("hub", "STARTACCEPTINGCONNECTIONS", "true", "SERVERIPS", "127.0.0.1@0");
    Recorder r = new Recorder();
    hub.requestNotification(r, "joined", new TRADEServiceConstraints().name("openGripper"), null, "joined");
    hub.requestNotification(r, "left", null, null, "left");
    TRADEContainer arm = container("arm", "CONNECTCONTAINERS", hub.getServerAddresses().get(0));
    arm.registerAllServices(new Gripper());
    Await.until(WAIT, () -> r.events.contains("joined openGripper@arm"), "joined from arm");
    arm.close();
    Await.until(WAIT, () -> r.events.contains("left openGripper@arm"), "left when arm closes");
    assertEquals(List.of("joined openGripper@arm", "left openGripper@arm"), r.events);
  }

  @Test
  void closingAContainerReportsNothingToItsListeners() throws TRADEException {
    TRADEContainer hub = container("hub", "STARTACCEPTINGCONNECTIONS", "true", "SERVERIPS", "127.0.0.1@0");
    TRADEContainer arm = container("arm", "CONNECTCONTAINERS", hub.getServerAddresses().get(0));
    arm.registerAllServices(new Gripper());
    Recorder r = new Recorder();
    hub.registerNotificationNowOrWhenJoined(r, new TRADEServiceConstraints().name("openGripper"), "joined");
    hub.requestNotification(r, "left", null, null, "left");
    Await.until(WAIT, () -> r.events.contains("joined openGripper@arm"), "joined from arm");
    hub.close();
    // The arm's service did not leave the system: the listener's own container went away.
    assertEquals(List.of("joined openGripper@arm"), r.events);
  }

  @Test
  void aThrowingCallbackDoesNotStopOtherDeliveries() throws TRADEException {
    TRADEContainer trade = container("throws");
    Recorder r = new Recorder();
    trade.requestNotification(r, "joined", null, null, "fails");
    trade.requestNotification(r, "joined", null, null, "joined");
    trade.registerAllServices(new Gripper());
    trade.registerAllServices(new Numbered());
    Await.until(WAIT, () -> r.events.size() == 2, "both joins despite the failing callback");
    assertEquals(List.of("joined openGripper@throws", "joined number@throws"), r.events);
  }

  @Test
  void cancelledRequestsStopAndNullCancelsAllOfAType() throws TRADEException {
    TRADEContainer trade = container("cancel");
    Recorder r = new Recorder();
    trade.requestNotification(r, "joined", new TRADEServiceConstraints().name("number"), null, "joined");
    trade.requestNotification(r, "joined", new TRADEServiceConstraints().name("openGripper"), null, "joined");
    trade.cancelNotification(r, "joined", new TRADEServiceConstraints().name("number"));
    trade.registerAllServices(new Numbered());
    trade.registerAllServices(new Gripper());
    Await.until(WAIT, () -> r.events.size() == 1, "one join");
    trade.cancelNotification(r, "joined", null);
    trade.registerAllServices(new Gripper());
    // A marker request registered after the cancel proves the queue drained past that change.
    Recorder marker = new Recorder();
    trade.registerNotificationNowOrWhenJoined(marker, new TRADEServiceConstraints().name("number"), "joined");
    Await.until(WAIT, () -> marker.events.size() == 1, "marker");
    assertEquals(List.of("joined openGripper@cancel"), r.events);
  }

  @Test
  void badRequestsAreTypedErrorsNamingTheProblem() {
    TRADEContainer trade = container("bad");
    Recorder r = new Recorder();
    TRADEBadArgumentsException type = assertThrows(TRADEBadArgumentsException.class,
        () -> trade.requestNotification(r, "sometimes", null, null, "joined"));
    assertEquals("Unknown notification type 'sometimes'; supported: joined, left, once, after, at,"
        + " every, if, when", type.getMessage());
    TRADEBadArgumentsException missing = assertThrows(TRADEBadArgumentsException.class,
        () -> trade.requestNotification(r, "joined", null, null, "nothing"));
    assertTrue(missing.getMessage().startsWith("Callback org.example.net.NotificationsTest$Recorder"
        + ".nothing not usable: there is no public method"), missing.getMessage());
    TRADEBadArgumentsException plain = assertThrows(TRADEBadArgumentsException.class,
        () -> trade.requestNotification(r, "joined", null, null, "notAService"));
    assertTrue(plain.getMessage().endsWith("it must carry @TRADEService (callbacks are services)"),
        plain.getMessage());
  }

  @Test
  void nowOrWhenJoinedDeliversEachServiceExactlyOnceUnderConcurrentJoins() throws Exception {
    TRADEContainer trade = container("race");
    for (int i = 0; i < 50; i++) {
      trade.registerAllServices(new Numbered(), "race");
    }
    ExecutorService pool = Executors.newFixedThreadPool(4);
    CountDownLatch go = new CountDownLatch(1);
    for (int t = 0; t < 4; t++) {
      pool.execute(() -> {
        try {
          go.await();
          for (int i = 0; i < 50; i++) {
            trade.registerAllServices(new Numbered(), "race");
          }
        } catch (Exception e) {
          throw new AssertionError(e);
        }
      });
    }
    Set<TRADEServiceInfo> seen = Collections.synchronizedSet(new HashSet<>());
    List<TRADEServiceInfo> all = Collections.synchronizedList(new ArrayList<>());
    Object listener = new Object() {
      @TRADEService
      public void got(TRADEServiceInfo info) {
        seen.add(info);
        all.add(info);
      }
    };
    go.countDown();
    trade.registerNotificationNowOrWhenJoined(listener, new TRADEServiceConstraints().inGroups("race"), "got");
    pool.shutdown();
    assertTrue(pool.awaitTermination(30, TimeUnit.SECONDS));
    Await.until(WAIT, () -> seen.size() == 250, "all 250 services delivered");
    assertEquals(250, all.size(), "no service delivered twice");
  }
}
