package dev.trade.internal.notify;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.Executor;
import java.util.function.Predicate;

/** Holds tasks until the test runs them: a delivery "still running" is one not run yet. */
final class ManualExecutor implements Executor {
  private final Deque<Runnable> queue = new ArrayDeque<>();

  @Override
  public synchronized void execute(Runnable task) {
    queue.add(task);
  }

  synchronized int queued() {
    return queue.size();
  }

  /** Runs the queued tasks (and those they queue) in order. */
  void runAll() {
    runAll(r -> true);
  }

  /** Runs the queued tasks that are {@code ready} (and those they queue) in order; keeps the rest. */
  void runAll(Predicate<Runnable> ready) {
    Deque<Runnable> kept = new ArrayDeque<>();
    while (true) {
      Runnable r;
      synchronized (this) {
        r = queue.poll();
        if (r == null) {
          queue.addAll(kept);
          return;
        }
      }
      if (ready.test(r)) {
        r.run();
      } else {
        kept.add(r);
      }
    }
  }
}
