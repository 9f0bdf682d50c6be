package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.codec.TestTypes.Color;
import dev.trade.internal.codec.TestTypes.Labeled;
import dev.trade.internal.codec.TestTypes.Point;
import dev.trade.internal.codec.TestTypes.Pose;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** One codec shared by many threads, while the allow-list grows. */
class CodecConcurrencyTest {

  @Test
  void sharedCodecRoundTripsFromManyThreads() throws Exception {
    Codec codec = TestTypes.codec();
    int threads = 8;
    ExecutorService pool = Executors.newFixedThreadPool(threads);
    CountDownLatch start = new CountDownLatch(1);
    try {
      List<Future<Integer>> results = new ArrayList<>();
      for (int t = 0; t < threads; t++) {
        int id = t;
        Callable<Integer> task = () -> {
          start.await();
          int done = 0;
          for (int i = 0; i < 2_000; i++) {
            Object value = List.of(new Labeled("t" + id, new Point(id, i), List.of("x"), i, Color.RED),
                new Pose(i, id, i, "f"), "s" + i, i);
            assertEquals(value, codec.decode(codec.encode(value), loader()));
            if (i % 500 == 0) {
              codec.allowList().add("com.example" + id + ".*");
            }
            done++;
          }
          return done;
        };
        results.add(pool.submit(task));
      }
      start.countDown(); // all threads meet the classes for the first time together
      for (Future<Integer> result : results) {
        assertEquals(2_000, result.get(60, TimeUnit.SECONDS));
      }
    } finally {
      pool.shutdownNow();
    }
  }
}
