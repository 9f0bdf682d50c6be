package dev.trade.internal.hooks;

import dev.trade.internal.call.Invocation;

/**
 * Sees every call the host chain runs, as a pair of events: {@link #start} before the service
 * (and its hooks) and {@link #end} after. For statistics, not for users (hooks are for users):
 * implementations must be fast, must not block and must not throw; the chain drops what they
 * throw anyway. Implementations are safe for concurrent use.
 */
interface CallObserver {
  /** A call starts; returns what {@link #end} is given back (a start time, say). */
  long start(Invocation call);

  /** The call ended, by returning ({@code failure} null) or with {@code failure}. */
  void end(Invocation call, long started, Throwable failure);
}
