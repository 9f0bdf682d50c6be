package dev.trade.internal.call;

import dev.trade.TRADEException;

/**
 * The call a thread is running, for the few services that must know who calls them (the lock
 * service, the notification service): the host chain binds it around calls to those services only
 * (see {@code LockLink}), so that other calls pay nothing for it.
 */
public final class CurrentCall {
  private static final ThreadLocal<Invocation> CURRENT = new ThreadLocal<>();

  private CurrentCall() {}

  /** The call to a caller-bound service this thread is running, or null. */
  public static Invocation get() {
    return CURRENT.get();
  }

  /** Runs the rest of the chain with {@code call} bound for the service it reaches. */
  public static Object bound(Invocation call, CallLink.Next next) throws TRADEException {
    Invocation outer = CURRENT.get();
    CURRENT.set(call);
    try {
      return next.proceed(call);
    } finally {
      if (outer == null) {
        CURRENT.remove();
      } else {
        CURRENT.set(outer);
      }
    }
  }
}
