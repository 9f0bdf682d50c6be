package dev.trade.internal.net;

import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The network's control thread: runs state changes one at a time, in order, and after a burst of
 * them runs {@code afterBurst} (which writes the frames they queued), once the queue is empty or
 * every {@link #MAX_BURST} tasks, so that no frame waits long behind a steady stream of tasks.
 */
final class ControlExecutor extends ThreadPoolExecutor {
  static final int MAX_BURST = 32;

  private final Runnable afterBurst;
  private int sinceLast; // control thread only

  ControlExecutor(ThreadFactory threads, Runnable afterBurst) {
    super(1, 1, 0, TimeUnit.MILLISECONDS, new LinkedBlockingQueue<>(), threads);
    this.afterBurst = afterBurst;
  }

  @Override
  protected void afterExecute(Runnable task, Throwable failure) {
    if (getQueue().isEmpty() || ++sinceLast >= MAX_BURST) {
      sinceLast = 0;
      afterBurst.run();
    }
  }

  /** Daemon threads named {@code prefix-1}, {@code prefix-2}, …: containers never keep a JVM up. */
  static ThreadFactory daemon(String prefix) {
    AtomicInteger n = new AtomicInteger();
    return r -> {
      Thread t = new Thread(r, prefix + "-" + n.incrementAndGet());
      t.setDaemon(true);
      return t;
    };
  }
}
