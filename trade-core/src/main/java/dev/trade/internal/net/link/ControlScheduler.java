package dev.trade.internal.net.link;

/**
 * Runs a task on the network's control thread after a delay: how replication, routing and link
 * swaps come back to a decision later without owning a thread or a timer.
 */
public interface ControlScheduler {
  /** Runs {@code task} on the control thread after {@code delayNanos}; nothing once closed. */
  void schedule(Runnable task, long delayNanos);
}
