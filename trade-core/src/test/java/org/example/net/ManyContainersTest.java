package org.example.net;

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
import java.util.Collections;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Enough containers, found by multicast on loopback, that each links to only some of the others:
 * every container still sees every service, calls to containers without a direct link are
 * forwarded, and a container that leaves is seen to leave by all.
 */
class ManyContainersTest {
  private static final int N = 24;
  /**
   * A container dials at most ⌈log₂ 24⌉ + 2 = 7 others and is dialled by about as many; links made
   * while views of the membership still grew stay too. A full mesh would be 23.
   */
  private static final int MAX_NEIGHBOURS = 20;
  private static final double MAX_MEAN_NEIGHBOURS = 14;
  private static final Duration WAIT = Duration.ofSeconds(30);
  private static final TRADEServiceConstraints WHO = new TRADEServiceConstraints().name("whoAmI");
  private final List<TRADEContainer> containers = new ArrayList<>();

  public static class LeftRecorder {
    final List<String> left = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void left(TRADEServiceInfo info) {
      left.add(info.getContainerName());
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

  @Test
  void manyContainersLinkToFewConvergeForwardAndSeeOneLeave() throws TRADEException {
    Swarm.start(N, containers);
    for (TRADEContainer c : containers) {
      Await.until(WAIT, () -> c.getAvailableServices(WHO).size() == N, "all services on " + c.getName());
    }

    int most = 0;
    int total = 0;
    List<Integer> counts = new ArrayList<>();
    for (TRADEContainer c : containers) {
      int n = c.getNeighbours().size();
      most = Math.max(most, n);
      total += n;
      counts.add(n);
    }
    assertTrue(most <= MAX_NEIGHBOURS, "a container has " + most + " neighbours: " + counts);
    assertTrue(total / (double) N <= MAX_MEAN_NEIGHBOURS, "neighbours: " + counts);

    TRADEContainer from = containers.get(0);
    TRADEServiceInfo far = farService(from);
    assertTrue(far.getDistance() > 1, "distance " + far.getDistance());
    assertEquals(far.getContainerName() + " answers c0", far.call(String.class, "c0"));

    List<LeftRecorder> recorders = new ArrayList<>();
    TRADEContainer leaving = containers.get(N / 2);
    for (TRADEContainer c : containers) {
      if (c != leaving) {
        LeftRecorder r = new LeftRecorder();
        c.requestNotification(r, "left", WHO, null, "left");
        recorders.add(r);
      }
    }
    leaving.close();
    for (int i = 0; i < recorders.size(); i++) {
      LeftRecorder r = recorders.get(i);
      Await.until(Duration.ofSeconds(5), () -> r.left.contains(leaving.getName()),
          "recorder " + i + " told that " + leaving.getName() + " left");
    }
    for (TRADEContainer c : containers) {
      if (c != leaving) {
        Await.until(WAIT, () -> c.getAvailableServices(WHO).size() == N - 1,
            "the others' services on " + c.getName() + " after one left");
      }
    }
    TRADEServiceInfo stillFar = farService(from);
    assertEquals(stillFar.getContainerName() + " answers c0", stillFar.call(String.class, "c0"));
  }

  /**
   * A service of a container {@code from} has no direct link to. Links may still come up while the
   * overlay settles, and distances follow a new link within the link-state flood interval, so a
   * service still listed at distance 2 may already be a neighbour's: those are skipped.
   */
  private static TRADEServiceInfo farService(TRADEContainer from) {
    Set<String> neighbours = Set.copyOf(from.getNeighbours());
    for (TRADEServiceInfo s : from.getAvailableServices(WHO)) {
      if (s.getDistance() > 1 && !neighbours.contains(s.getContainerId())) {
        return s;
      }
    }
    throw new AssertionError(from.getName() + " links directly to all of " + neighbours.size());
  }
}
