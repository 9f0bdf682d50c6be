package dev.trade.internal.call;

import dev.trade.TRADEException;

/**
 * One link of the call chain (hooks, lock checks, routing, invocation). A link either answers the
 * call itself or passes it on with {@code next.proceed(call)} exactly once. Implementations must be
 * thread-safe: many calls go through a link at once.
 */
public interface CallLink {
  Object proceed(Invocation call, Next next) throws TRADEException;

  /** The rest of the chain after a link. */
  interface Next {
    Object proceed(Invocation call) throws TRADEException;
  }
}
