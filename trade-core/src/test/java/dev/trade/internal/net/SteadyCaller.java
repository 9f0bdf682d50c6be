package dev.trade.internal.net;

import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A well-behaved user that calls one service in a loop on its own thread while a test attacks the
 * container that provides it. Every call must succeed.
 */
final class SteadyCaller implements AutoCloseable {
  private final TRADEServiceInfo service;
  private final Object[] args;
  private final AtomicLong successes = new AtomicLong();
  private final List<Throwable> failures = new CopyOnWriteArrayList<>();
  private final Thread thread;
  private volatile boolean stopped;

  SteadyCaller(TRADEServiceInfo service, Object... args) {
    this.service = service;
    this.args = args;
    this.thread = new Thread(this::run, "steady-caller");
    thread.setDaemon(true);
    thread.start();
  }

  private void run() {
    while (!stopped) {
      try {
        service.call(Object.class, args);
        successes.incrementAndGet();
      } catch (Exception | Error e) {
        failures.add(e);
      }
    }
  }

  long successes() {
    return successes.get();
  }

  /** Waits until {@code n} more calls succeed, proving the service still answers now. */
  void awaitMore(int n) {
    long target = successes() + n;
    Await.until(Duration.ofSeconds(10), () -> successes() >= target || !failures.isEmpty(),
        n + " more successful calls");
    assertNoFailures();
  }

  void assertNoFailures() {
    if (!failures.isEmpty()) {
      AssertionError e = new AssertionError(failures.size() + " calls failed; the first:",
          failures.get(0));
      throw e;
    }
  }

  @Override
  public void close() throws InterruptedException {
    stopped = true;
    thread.join(10_000);
  }
}
