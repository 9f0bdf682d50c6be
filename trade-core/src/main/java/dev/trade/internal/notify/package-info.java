/**
 * Notifications: triggers, their delivery, and the notification service (docs/notifications.md).
 *
 * <p>{@link dev.trade.internal.notify.NotificationService} is this container's system service;
 * {@link dev.trade.internal.notify.Notifications} is its engine, which owns the live
 * notifications; {@link dev.trade.internal.notify.NotificationClient} is the requester's side that
 * the static API uses, and reaches an engine only through a service call. Threads: the container's
 * timer ({@link dev.trade.internal.time.Scheduler}, which tests drive with a fake clock), a pool
 * of delivery threads for timed types, one ordered event thread for joined and left; all start with their first use.
 * Words: a notification is <em>due</em> at a time on its grid, <em>delivered</em> when its
 * condition, service and callback have been called, <em>skipped</em> when it was due while its
 * previous delivery still ran, and <em>ended</em> once, with a reason.
 */
package dev.trade.internal.notify;
