package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Load (docs/reliability.md): 64 callers in one container call a provider in another JVM,
 * {@code -Dtrade.load.calls} calls in all (64,000 unless set; the full run makes 1,000,000), and
 * not one is lost, run twice or answered with another call's reply. Then, with the 64 callers
 * still calling, the provider is killed with SIGKILL: every call in flight ends with the typed
 * unavailable error within a second.
 */
@Timeout(3_600)
class LoadTest {
  private static final Duration START = Duration.ofSeconds(30);
  private static final int CALLERS = 64;
  private static final long LIMIT_MS = 1000;

  @Test
  void everyCallAnsweredOnceThenEveryCallInFlightEndsTypedWhenTheProviderIsKilled() throws Exception {
    long calls = Long.getLong("trade.load.calls", 64_000);
    long perCaller = calls / CALLERS;
    try (JvmProcess provider = ProviderMain.launch(List.of(), "CONTAINERNAME=provider",
        "STARTACCEPTINGCONNECTIONS=true", "SERVERIPS=127.0.0.1@0");
        // A lost reply fails its call after 20 s instead of hanging the test.
        TRADEContainer caller = TRADEContainer.builder().name("caller").property("CALLTIMEOUT", "20000")
            .property("CONNECTCONTAINERS", ProviderMain.address(provider.awaitLine("READY ", START)))
            .build()) {
      TRADEServiceConstraints mixed = new TRADEServiceConstraints().name("mixed");
      Await.until(START, () -> !caller.getAvailableServices(mixed).isEmpty(), "the provider's services");
      TRADEServiceInfo mix = caller.getAvailableService(new TRADEServiceConstraints().name("mix"));

      Queue<String> problems = new ConcurrentLinkedQueue<>();
      long start = System.nanoTime();
      runCallers(t -> {
        for (long i = 0; i < perCaller; i++) {
          long x = (long) t << 32 | i;
          String reply = mix.call(String.class, x);
          if (!expected(x).equals(reply)) {
            problems.add("call " + x + " got " + reply);
          }
        }
      }, problems);
      double seconds = (System.nanoTime() - start) / 1e9;
      long ran = caller.getAvailableService(mixed).call(long.class);
      System.out.printf("load: %d calls from %d callers in %.1f s (%.0f calls/s); failed or mismatched %d;"
          + " runs at the provider %d%n", perCaller * CALLERS, CALLERS, seconds, perCaller * CALLERS / seconds,
          problems.size(), ran);
      assertEquals(List.of(), List.copyOf(problems).subList(0, Math.min(10, problems.size())));
      // Each reply names its own argument, so each call ran at least once; as many runs as calls
      // then means none ran twice.
      assertEquals(perCaller * CALLERS, ran, "runs of mix at the provider");

      killMidLoad(provider, mix);
    }
  }

  private interface Body {
    void run(int caller) throws Exception;
  }

  private static void runCallers(Body body, Queue<String> problems) throws InterruptedException {
    CountDownLatch done = new CountDownLatch(CALLERS);
    for (int t = 0; t < CALLERS; t++) {
      int caller = t;
      Thread thread = new Thread(() -> {
        try {
          body.run(caller);
        } catch (Exception e) {
          problems.add(Thread.currentThread().getName() + ": " + e);
        } finally {
          done.countDown();
        }
      }, "load-caller-" + t);
      thread.setDaemon(true);
      thread.start();
    }
    done.await();
  }

  private static String expected(long x) {
    return x + ":" + Long.toHexString(ConcurrentCallersTest.scramble(x));
  }

  /** The 64 callers call on until a call fails; the provider is killed while they do. */
  private static void killMidLoad(JvmProcess provider, TRADEServiceInfo mix) throws Exception {
    AtomicLong succeeded = new AtomicLong();
    List<CompletableFuture<Throwable>> ends = new ArrayList<>();
    List<Long> endedAt = new ArrayList<>();
    for (int t = 0; t < CALLERS; t++) {
      CompletableFuture<Throwable> end = new CompletableFuture<>();
      ends.add(end);
      endedAt.add(0L);
      int caller = t;
      Thread thread = new Thread(() -> {
        long x = (long) (CALLERS + caller) << 32;
        try {
          while (true) {
            x++;
            if (!expected(x).equals(mix.call(String.class, x))) {
              throw new AssertionError("call " + x + " got another's reply");
            }
            succeeded.incrementAndGet();
          }
        } catch (Throwable e) {
          synchronized (endedAt) {
            endedAt.set(caller, System.nanoTime());
          }
          end.complete(e);
        }
      }, "kill-caller-" + t);
      thread.setDaemon(true);
      thread.start();
    }
    Await.until(START, () -> succeeded.get() >= 10L * CALLERS, "calls flowing before the kill");
    long killedAt = System.nanoTime();
    provider.kill();
    List<Throwable> errors = new ArrayList<>();
    for (CompletableFuture<Throwable> end : ends) {
      try {
        errors.add(end.get(20, TimeUnit.SECONDS));
      } catch (TimeoutException e) {
        throw new AssertionError("a caller still waits 20 s after the provider was killed", e);
      }
    }
    long worst;
    synchronized (endedAt) {
      worst = endedAt.stream().mapToLong(at -> TimeUnit.NANOSECONDS.toMillis(at - killedAt)).max()
          .orElseThrow();
    }
    System.out.printf("load: kill -9 of the provider with %d callers calling: every call ended typed,"
        + " the last %d ms after the kill%n", CALLERS, worst);
    for (Throwable e : errors) {
      assertTrue(e instanceof TRADEServiceUnavailableException, "what a caller got: " + e);
    }
    assertTrue(worst <= LIMIT_MS, "callers failed up to " + worst + " ms after the kill");
  }
}
