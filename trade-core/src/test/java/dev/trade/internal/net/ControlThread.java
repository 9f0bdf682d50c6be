package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;

/** Holds a network's control thread, as a loaded JVM does for seconds, until released. */
final class ControlThread {
  private ControlThread() {}

  /** Queues a task that blocks the control thread of {@code net} until {@code release} opens. */
  static void block(Network net, CountDownLatch release) {
    assertTrue(net.onControl(() -> {
      try {
        release.await();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }), "the control thread takes tasks");
  }
}
