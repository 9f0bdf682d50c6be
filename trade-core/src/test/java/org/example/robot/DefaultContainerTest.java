package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import dev.trade.TRADE;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** The static facade over the JVM's default container. */
class DefaultContainerTest {
  @Test
  void defaultContainerIsCreatedOnceEvenUnderContention() throws Exception {
    ExecutorService pool = Executors.newFixedThreadPool(8);
    List<Future<TRADEContainer>> all = new ArrayList<>();
    Callable<TRADEContainer> get = TRADE::getDefaultContainer;
    for (int i = 0; i < 32; i++) {
      all.add(pool.submit(get));
    }
    TRADEContainer first = all.get(0).get(10, TimeUnit.SECONDS);
    for (Future<TRADEContainer> f : all) {
      assertSame(first, f.get(10, TimeUnit.SECONDS));
    }
    pool.shutdown();
  }

  @Test
  void staticMethodsWorkOnTheDefaultContainer() throws TRADEException {
    RobotArm arm = new RobotArm();
    TRADE.registerAllServices(arm, "facade");
    try {
      TRADE.getAvailableService(new TRADEServiceConstraints().inGroups("facade").name("openGripper"))
          .call(void.class, 7);
      assertEquals(List.of(7), arm.speeds);
      assertEquals(2, TRADE.getAvailableServices(new TRADEServiceConstraints().inGroups("facade")).size());
    } finally {
      TRADE.deregister(arm);
    }
    assertEquals(0, TRADE.getAvailableServices(new TRADEServiceConstraints().inGroups("facade")).size());
  }
}
