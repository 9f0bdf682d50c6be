package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** Registration, lookup and calls from many threads at once. */
class ConcurrencyTest {
  public static class Counter {
    final AtomicInteger hits = new AtomicInteger();

    @TRADEService
    public int hit(int by) {
      return hits.addAndGet(by);
    }
  }

  @Test
  void manyThreadsRegisterCallAndDeregisterWithoutLosingAnything() throws Exception {
    try (TRADEContainer trade = TRADEContainer.builder().build()) {
      Counter stable = new Counter();
      trade.registerAllServices(stable, "stable");
      ExecutorService pool = Executors.newFixedThreadPool(8);
      List<Future<Integer>> futures = new ArrayList<>();
      for (int t = 0; t < 8; t++) {
        int thread = t;
        futures.add(pool.submit(() -> {
          int unavailable = 0;
          TRADEServiceInfo s = trade.getAvailableService(
              new TRADEServiceConstraints().inGroups("stable").name("hit"));
          for (int i = 0; i < 2_000; i++) {
            s.call(int.class, 1);
            Counter mine = new Counter();
            List<TRADEServiceInfo> infos =
                new ArrayList<>(trade.registerAllServices(mine, "t" + thread));
            assertEquals(1, trade.getAvailableServices(
                new TRADEServiceConstraints().inGroups("t" + thread)).size());
            trade.deregister(mine);
            try {
              infos.get(0).call(int.class, 1);
            } catch (TRADEServiceUnavailableException expected) {
              unavailable++;
            }
          }
          return unavailable;
        }));
      }
      for (Future<Integer> f : futures) {
        assertEquals(2_000, f.get(60, TimeUnit.SECONDS));
      }
      pool.shutdown();
      assertTrue(pool.awaitTermination(10, TimeUnit.SECONDS));
      assertEquals(16_000, stable.hits.get());
      assertEquals(1, trade.getAvailableServices().size());
    }
  }

  @Test
  void callsRacingADeregistrationEitherRunOrFailUnavailable() throws Exception {
    try (TRADEContainer trade = TRADEContainer.builder().build()) {
      Counter c = new Counter();
      TRADEServiceInfo s = trade.registerAllServices(c).iterator().next();
      ExecutorService pool = Executors.newFixedThreadPool(4);
      AtomicInteger ok = new AtomicInteger();
      AtomicInteger gone = new AtomicInteger();
      List<Future<?>> futures = new ArrayList<>();
      for (int t = 0; t < 4; t++) {
        futures.add(pool.submit(() -> {
          for (int i = 0; i < 5_000; i++) {
            try {
              s.call(int.class, 1);
              ok.incrementAndGet();
            } catch (TRADEServiceUnavailableException e) {
              gone.incrementAndGet();
            } catch (TRADEException e) {
              throw new AssertionError(e);
            }
          }
          return null;
        }));
      }
      trade.deregister(c);
      for (Future<?> f : futures) {
        f.get(60, TimeUnit.SECONDS);
      }
      pool.shutdown();
      assertEquals(20_000, ok.get() + gone.get());
      assertEquals(ok.get(), c.hits.get());
    }
  }
}
