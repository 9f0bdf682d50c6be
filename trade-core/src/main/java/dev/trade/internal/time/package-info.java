/**
 * A container's time and its one timer.
 *
 * <p>A container owns one {@link dev.trade.internal.time.Scheduler}, made by the container and
 * closed by it last; networking and notifications are handed it and never close it. It has one
 * timer thread ({@code trade-timer-NAME}), started by the first task: heartbeats, dial retries,
 * the sweep of overdue calls, discovery's announcements and timed notifications all run on it, so
 * its tasks are short and hand anything that may block to a worker of their own.
 *
 * <p>Every decision that depends on time takes {@code now} as a parameter, read from the
 * scheduler's clock ({@link dev.trade.internal.time.Scheduler#nanoTime}) where the task runs, so
 * that a test can drive the same code on a fake clock and timer
 * ({@code dev.trade.testing.FakeScheduler}). Words: <em>now</em> is a reading of that clock, in
 * {@link java.lang.System#nanoTime} scale; a task is <em>due</em> when now has reached its time.
 */
package dev.trade.internal.time;
