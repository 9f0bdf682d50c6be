package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.discovery.LoopbackMulticast;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Three JVMs with no addresses configured find each other by multicast on loopback (range
 * localhost: lo, TTL 0), call across, and see a killed one leave.
 */
class DiscoveryAcrossJvmsTest {
  private static final Duration START = Duration.ofSeconds(30);

  /** Counts "left" events of the killed provider's services. */
  public static class Watcher {
    final CountDownLatch left = new CountDownLatch(1);
    volatile long leftAt;

    @TRADEService
    public void left(TRADEServiceInfo info) {
      if (info.getContainerName().equals("p2") && leftAt == 0) {
        leftAt = System.nanoTime();
        left.countDown();
      }
    }
  }

  @Test
  void threeJvmsDiscoverEachOtherCallAcrossAndSeeAKilledOneLeave() throws Exception {
    LoopbackMulticast.assumeUsable();
    String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
    // A minute's FAILURETIMEOUT: a killed JVM can only be noticed by its sockets' end, at once.
    String[] discovery = {"STARTDISCOVERY=true", "STARTBROADCAST=true", "BROADCASTPORT=" + port,
        "TRADESYSID=jvm-discovery", "FAILURETIMEOUT=60000"};
    try (JvmProcess p1 = ProviderMain.launch(List.of(), with(discovery, "CONTAINERNAME=p1"));
        JvmProcess p2 = ProviderMain.launch(List.of(), with(discovery, "CONTAINERNAME=p2"));
        TRADEContainer here = TRADEContainer.builder().name("here")
            .property("STARTDISCOVERY", "true").property("STARTBROADCAST", "true")
            .property("BROADCASTPORT", port).property("TRADESYSID", "jvm-discovery")
            .property("FAILURETIMEOUT", "60000").build()) {
      p1.awaitLine("READY ", START);
      p2.awaitLine("READY ", START);
      TRADEServiceConstraints upper = new TRADEServiceConstraints().name("upper");
      Await.until(START, () -> here.getAvailableServices(upper).size() == 2, "both providers");
      for (TRADEServiceInfo s : here.getAvailableServices(upper)) {
        assertEquals("ABC", s.call(String.class, "abc"));
      }
      // p1 calls p2: hand p1 a handle to p2's service; it calls it from its own container.
      TRADEServiceInfo p1CallBack = only(here, new TRADEServiceConstraints().name("callBack"), "p1");
      TRADEServiceInfo p2Upper = only(here, upper, "p2");
      assertEquals("p1", p1CallBack.getContainerName());
      // p1 and p2 link on their own: until p1 has a route to p2, its call fails typed.
      Await.until(START, () -> {
        try {
          return "XYZ".equals(p1CallBack.call(String.class, p2Upper, "xyz"));
        } catch (dev.trade.TRADEInvocationException e) {
          if (e.getCause() instanceof dev.trade.TRADEServiceUnavailableException) {
            return false;
          }
          throw new AssertionError(e);
        } catch (TRADEException e) {
          throw new AssertionError(e);
        }
      }, "p1 to call p2");

      // Three containers link fully, but "here" may see p1's services through p2 before its own
      // link to p1 is up; killed then, p2 would take p1's only route with it.
      Await.until(START, () -> here.getNeighbours().size() == 2, "here linked to p1 and p2");
      Watcher w = new Watcher();
      here.requestNotification(w, "left", new TRADEServiceConstraints().name("upper"), null, "left");
      long killed = System.nanoTime();
      p2.kill();
      // Well before FAILURETIMEOUT, with room for a busy machine.
      assertTrue(w.left.await(20, TimeUnit.SECONDS), "left of p2's services");
      long millis = TimeUnit.NANOSECONDS.toMillis(w.leftAt - killed);
      System.out.println("left " + millis + " ms after the kill");
      assertEquals(List.of("p1"), names(here.getAvailableServices(upper)),
          () -> "after p2's death, linked to " + here.getNeighbours());
    }
  }

  private static String[] with(String[] base, String extra) {
    List<String> all = new ArrayList<>(List.of(base));
    all.add(extra);
    return all.toArray(new String[0]);
  }

  private static TRADEServiceInfo only(TRADEContainer c, TRADEServiceConstraints k, String container)
      throws TRADEException {
    for (TRADEServiceInfo s : c.getAvailableServices(k)) {
      if (s.getContainerName().equals(container)) {
        return s;
      }
    }
    throw new AssertionError("no " + k + " in " + container);
  }

  private static List<String> names(java.util.Collection<TRADEServiceInfo> infos) {
    List<String> result = new ArrayList<>();
    infos.forEach(i -> result.add(i.getContainerName()));
    return result;
  }
}
