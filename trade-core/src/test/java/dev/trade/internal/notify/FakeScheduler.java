package dev.trade.internal.notify;

import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/** A scheduler whose clock moves only when a test says so; due tasks run in the test's thread. */
final class FakeScheduler implements Scheduler {
  private static final Instant EPOCH = Instant.parse("2025-01-01T00:00:00Z");

  private record Task(long at, long seq, Runnable run) {}

  private final List<Task> tasks = new ArrayList<>();
  private long now = 1_000_000_000L;
  private long seq;

  @Override
  public synchronized long nanoTime() {
    return now;
  }

  @Override
  public synchronized Instant instant() {
    return EPOCH.plusNanos(now);
  }

  @Override
  public synchronized Runnable schedule(Runnable task, long atNanos) {
    Task t = new Task(atNanos, seq++, task);
    tasks.add(t);
    return () -> {
      synchronized (this) {
        tasks.remove(t);
      }
    };
  }

  @Override
  public void close() {}

  /** How many tasks wait. */
  synchronized int pending() {
    return tasks.size();
  }

  /** Moves the clock forward by {@code millis}, running each task as its time comes. */
  void advanceMillis(long millis) {
    long until;
    synchronized (this) {
      until = now + millis * 1_000_000;
    }
    while (true) {
      Task next;
      synchronized (this) {
        next = tasks.stream().filter(t -> t.at <= until)
            .min(Comparator.comparingLong(Task::at).thenComparingLong(Task::seq)).orElse(null);
        if (next == null) {
          now = until;
          return;
        }
        tasks.remove(next);
        now = Math.max(now, next.at);
      }
      next.run.run();
    }
  }
}
