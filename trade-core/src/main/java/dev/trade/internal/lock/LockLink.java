package dev.trade.internal.lock;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.CurrentCall;
import dev.trade.internal.call.Invocation;
import java.util.UUID;
import java.util.function.LongSupplier;

/**
 * The host chain's lock check: a call to a service leased by a lock runs only under that lock
 * (its id and fencing token in the call's context, from the lock's owner); any other call is
 * refused at once with {@code TRADELockedException}, or waits within its deadline when it asked to
 * ({@link Locks#WAIT}). A call under a lock that does not hold the service is refused too. Calls to
 * the system services that must know who asks (the lock service, the notification service) run
 * with their invocation bound ({@link CurrentCall}): this link already looks at every call's
 * service, so the binding costs other calls nothing more.
 * Thread-safe: all state is in the {@link LeaseTable}.
 */
final class LockLink implements CallLink {
  /** The most a waiting call keeps for its refusal to travel back: see {@link #waitDeadline}. */
  static final long MARGIN = 500_000_000L;

  private final LeaseTable table;
  private final LongSupplier clock;
  private final Holders holders;
  /** Service ids whose calls run with their invocation bound, added once they are registered. */
  private volatile long[] boundIds = new long[0];

  LockLink(LeaseTable table, LongSupplier clock, Holders holders) {
    this.table = table;
    this.clock = clock;
    this.holders = holders;
  }

  synchronized void bindCaller(long[] ids) {
    long[] all = java.util.Arrays.copyOf(boundIds, boundIds.length + ids.length);
    System.arraycopy(ids, 0, all, boundIds.length, ids.length);
    boundIds = all;
  }

  @Override
  public Object proceed(Invocation call, Next next) throws TRADEException {
    CallContext context = call.context();
    String lockText = context.isEmpty() ? null : context.get(Locks.LOCK);
    long service = call.service().serviceId();
    if (lockText == null && !context.isEmpty() && context.get(Locks.TOKEN) != null) {
      throw new TRADEBadArgumentsException("Call context has " + Locks.TOKEN + " without "
          + Locks.LOCK + " (docs/protocol.md, \"Call context\")\n    for service "
          + call.service().signature());
    }
    if (lockText == null && table.unused()) {
      return isBound(service) ? CurrentCall.bound(call, next) : next.proceed(call);
    }
    UUID lock = lockText == null ? null : parseLock(call, lockText);
    long token = lockText == null ? 0 : parseToken(call, context.get(Locks.TOKEN));
    LeaseTable.Admission a;
    if ("true".equals(context.get(Locks.WAIT))) {
      try {
        a = table.awaitAdmission(service, lock, token, call.caller().container(),
            waitDeadline(call.deadlineNanos(), clock.getAsLong()), clock);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        throw CallErrors.locked(call.service(), "interrupted while waiting for the lock");
      }
    } else {
      a = table.admit(service, lock, token, call.caller().container(), clock.getAsLong());
    }
    if (!a.admitted()) {
      throw CallErrors.locked(call.service(), a.why() + (a.blocker() == null ? ""
          : "; " + holders.describe(a.blocker())) + (a.mayWait() ? "; wait for it with"
          + " TRADEServiceInfo.waitingForLock(), or call under that lock" : ""));
    }
    return isBound(service) ? CurrentCall.bound(call, next) : next.proceed(call);
  }

  /**
   * When a call that waits for a lock gives up: a quarter of its time, at most {@link #MARGIN},
   * before its deadline, so that the refusal reaches a remote caller before it stops waiting.
   */
  static long waitDeadline(long deadline, long now) {
    long left = deadline - now;
    return left <= 0 ? deadline : deadline - Math.min(left / 4, MARGIN);
  }

  private boolean isBound(long service) {
    for (long id : boundIds) {
      if (id == service) {
        return true;
      }
    }
    return false;
  }

  private static UUID parseLock(Invocation call, String text) throws TRADEBadArgumentsException {
    try {
      return UUID.fromString(text);
    } catch (IllegalArgumentException e) {
      throw new TRADEBadArgumentsException("Call context " + Locks.LOCK + " '" + text
          + "' is not a lock id (a UUID in its canonical text)\n    for service "
          + call.service().signature());
    }
  }

  private static long parseToken(Invocation call, String text) throws TRADEBadArgumentsException {
    try {
      long token = Long.parseLong(text == null ? "" : text);
      if (token > 0) {
        return token;
      }
    } catch (NumberFormatException e) {
      // reported below
    }
    throw new TRADEBadArgumentsException("Call context " + Locks.TOKEN + " '" + text + "' is not a"
        + " fencing token (a positive decimal number, required with " + Locks.LOCK
        + ")\n    for service " + call.service().signature());
  }

  /** Words for a blocker: the lock, its owner container by name, principal, since when. */
  interface Holders {
    String describe(LeaseTable.Blocker b);
  }
}
