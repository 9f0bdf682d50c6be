package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * A component's own JVM shutdown hook may still use the static {@code TRADE} methods, as DIARC's
 * does to deregister: the default container is not closed by a shutdown hook of its own, which
 * would run at the same time and make the component's deregistration fail (before, it threw
 * {@code IllegalStateException}, and whatever else the hook had to do, such as stopping motors, was
 * skipped). The component's services leave when it deregisters them, and its links end with its
 * process.
 */
class DeregisterAtExitTest {
  private static final Duration WAIT = Duration.ofSeconds(30);

  /** Told when the component's services leave. */
  public static final class Watcher {
    final CountDownLatch left = new CountDownLatch(1);

    @TRADEService
    public void left(TRADEServiceInfo info) {
      left.countDown();
    }
  }

  @Test
  void aComponentsShutdownHookDeregistersThroughTheStaticMethods() throws Exception {
    Watcher watcher = new Watcher();
    TRADEServiceConstraints lamp = new TRADEServiceConstraints().name("lampOn");
    try (TRADEContainer peer = Hubs.hubBuilder("peer").build()) {
      peer.registerAllServices(watcher); // its service tells the component that the link is up
      peer.requestNotification(watcher, "left", lamp, null, "left");
      try (JvmProcess component = JvmProcess.start(ShutdownHookMain.class, List.of(),
          "CONTAINERNAME=component", "CONNECTCONTAINERS=" + peer.getServerAddresses().get(0))) {
        component.awaitLine("READY", WAIT);
        // Seen, or already gone again: the component exits as soon as it is ready.
        Await.until(WAIT, () -> !peer.getAvailableServices(lamp).isEmpty()
            || watcher.left.getCount() == 0, "the component's service");
        // The component is exiting. A shutdown hook that closed its default container would have
        // said goodbye by now, and its service would leave here; give it that chance.
        watcher.left.await(2, TimeUnit.SECONDS);
        component.close(); // ends its input: its own hook deregisters now
        assertEquals("DEREGISTERED", component.awaitLine("", WAIT));
        assertEquals(0, component.awaitExit(WAIT));
      }
      Await.until(WAIT, () -> watcher.left.getCount() == 0, "the component's service to leave");
    }
  }
}
