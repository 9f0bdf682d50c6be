package dev.trade.internal.call;

import dev.trade.internal.registry.ServiceDescriptor;

/**
 * One call on its way through the chain: which service, with which arguments, until when, from
 * whom ({@link Caller}) and with what context ({@link CallContext}).
 * The argument array is owned by the chain: links may replace it (a copy), never mutate the
 * caller's. Not thread-safe: an invocation travels the chain on one thread.
 *
 * <p>A call that arrived from another container carries the caller's deadline. A call made in
 * this container has a timeout instead and fixes its deadline when a link first asks for it: the
 * clock is read only if someone needs it, because reading it costs about as much as the rest of a
 * local call (docs/benchmarks-log.md) and a local invocation is not timed.
 */
public final class Invocation {
  private final ServiceDescriptor service;
  private final Object[] args;
  private final long timeoutNanos;
  private final Caller caller;
  private final CallContext context;
  private long deadlineNanos;
  private boolean fixed;

  /**
   * @param service the service to call
   * @param args the arguments, already normalized (never null)
   * @param deadlineNanos {@link System#nanoTime()} value after which the caller stops waiting
   */
  public Invocation(ServiceDescriptor service, Object[] args, long deadlineNanos, Caller caller,
      CallContext context) {
    this(service, args, 0, deadlineNanos, true, caller, context);
  }

  private Invocation(ServiceDescriptor service, Object[] args, long timeoutNanos, long deadlineNanos,
      boolean fixed, Caller caller, CallContext context) {
    this.service = service;
    this.args = args;
    this.timeoutNanos = timeoutNanos;
    this.caller = caller;
    this.context = context;
    this.deadlineNanos = deadlineNanos;
    this.fixed = fixed;
  }

  /** A call made in this container, whose deadline is {@code timeoutNanos} from when it is asked. */
  public static Invocation local(ServiceDescriptor service, Object[] args, long timeoutNanos,
      Caller caller, CallContext context) {
    return new Invocation(service, args, timeoutNanos, 0, false, caller, context);
  }

  public ServiceDescriptor service() {
    return service;
  }

  public Object[] args() {
    return args;
  }

  /** Who makes the call. */
  public Caller caller() {
    return caller;
  }

  /** The call's context: {@link CallContext#EMPTY} for most calls. */
  public CallContext context() {
    return context;
  }

  /** The {@link System#nanoTime()} value after which the caller stops waiting. */
  public long deadlineNanos() {
    if (!fixed) {
      deadlineNanos = System.nanoTime() + timeoutNanos;
      fixed = true;
    }
    return deadlineNanos;
  }

  /** Nanoseconds left before the deadline (negative once it passed). */
  public long remainingNanos() {
    return deadlineNanos() - System.nanoTime();
  }

  /** The same call with other arguments (and the same deadline). */
  public Invocation withArgs(Object[] newArgs) {
    return new Invocation(service, newArgs, 0, deadlineNanos(), true, caller, context);
  }

  @Override
  public String toString() {
    return "Invocation[" + service.signature() + ", " + args.length + " args]";
  }
}
