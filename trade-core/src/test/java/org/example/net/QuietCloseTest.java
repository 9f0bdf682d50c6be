package org.example.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.discovery.LoopbackMulticast;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Containers found by discovery close one after another while their neighbours' links go down
 * around them: no thread of theirs fails on the way (a closing container has no routes to follow
 * and no one to dial again; its timer and workers are gone).
 */
@Timeout(60)
class QuietCloseTest {
  private static final int N = 16;

  @Test
  void closingContainersThrowNothingOnTheirThreads() throws Exception {
    LoopbackMulticast.assumeUsable();
    List<String> failures = Collections.synchronizedList(new ArrayList<>());
    Thread.UncaughtExceptionHandler before = Thread.getDefaultUncaughtExceptionHandler();
    Thread.setDefaultUncaughtExceptionHandler((t, e) -> failures.add(t.getName() + ": " + e));
    List<TRADEContainer> containers = new ArrayList<>();
    try {
      Swarm.start(N, containers);
      TRADEServiceConstraints who = new TRADEServiceConstraints().name("whoAmI");
      for (TRADEContainer c : containers) {
        Await.until(Duration.ofSeconds(30), () -> c.getAvailableServices(who).size() == N,
            "all services on " + c.getName());
      }
      containers.forEach(TRADEContainer::close);
    } finally {
      containers.forEach(TRADEContainer::close);
      Thread.setDefaultUncaughtExceptionHandler(before);
    }
    assertEquals(List.of(), failures);
  }
}
