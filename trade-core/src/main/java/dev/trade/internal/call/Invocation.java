package dev.trade.internal.call;

import dev.trade.internal.registry.ServiceDescriptor;

/**
 * One call on its way through the chain: which service, with which arguments, until when.
 * The argument array is owned by the chain: links may replace it (a copy), never mutate the
 * caller's. Immutable.
 *
 * @param service the service to call
 * @param args the arguments, already normalized (never null)
 * @param deadlineNanos {@link System#nanoTime()} value after which the caller stops waiting
 */
public record Invocation(ServiceDescriptor service, Object[] args, long deadlineNanos) {

  /** Nanoseconds left before the deadline (negative once it passed). */
  public long remainingNanos() {
    return deadlineNanos - System.nanoTime();
  }

  public Invocation withArgs(Object[] newArgs) {
    return new Invocation(service, newArgs, deadlineNanos);
  }
}
