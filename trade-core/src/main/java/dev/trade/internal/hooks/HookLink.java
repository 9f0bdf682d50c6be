package dev.trade.internal.hooks;

import dev.trade.TRADEException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.hooks.HookTable.OnTarget;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The hooks link of the host chain: calls a target's before hooks, the rest of the chain, then its
 * after hooks, as docs/hooks.md describes. A call this link has nothing to do for ({@link
 * #concerns}: no hooks on its service, no hook path, no observer) need not pass it: one more link
 * in the chain costs about 20 ns a call, as much as the rest of a local call's chain
 * (docs/benchmarks.md, "Hooks"), so the container runs such calls through the chain without it.
 *
 * <p>Each wrapper gets an array of its own; the target gets exactly the caller's arguments and the
 * caller exactly the target's result or failure, whatever a hook does. A hook that fails, times
 * out or whose wrapper is gone is counted and logged (the first failure of each hook at WARNING,
 * later ones at DEBUG) and never fails the call. Synchronous hooks wait at most the hook timeout
 * and never past the call's own deadline: a remote wrapper is called with that deadline, a local
 * one runs on a thread of {@link LocalWrappers} while the call waits for it; asynchronous ones run on this link's pool (two daemon
 * threads, made at first use, a queue of {@value #QUEUE}; a hook call that does not fit is
 * dropped and counted as a failure). Safe for concurrent use.
 */
final class HookLink implements CallLink {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");
  static final int QUEUE = 10_000;

  private final HookTable table;
  private final ServiceCaller caller;
  private final long timeoutNanos;
  private final String name;
  private volatile CallObserver observer;
  private final LocalWrappers local;
  private ExecutorService pool; // Guarded by this.
  private boolean closed; // Guarded by this.

  /**
   * @param caller calls the wrappers (this container, so through their host chains)
   * @param timeoutNanos the longest a synchronous hook delays a call (HOOKTIMEOUT)
   */
  HookLink(HookTable table, ServiceCaller caller, long timeoutNanos, String name) {
    this.table = table;
    this.caller = caller;
    this.timeoutNanos = timeoutNanos;
    this.name = name;
    this.local = new LocalWrappers(name);
  }

  /** Starts or (null) stops observing every call. */
  void observe(CallObserver o) {
    observer = o;
  }

  /**
   * Whether this link has anything to do for {@code call}: hooks on its service, an observer, or a
   * context (which may carry a hook path). When it has not, the container may run the call through
   * its host chain without this link ({@link Hooks#concerns}).
   */
  boolean concerns(Invocation call) {
    // CallContext.of gives EMPTY for every empty context, so identity tells emptiness.
    return call.context() != CallContext.EMPTY || observer != null
        || table.of(call.service().serviceId()) != null;
  }

  @Override
  public Object proceed(Invocation call, Next next) throws TRADEException {
    OnTarget hooks = table.of(call.service().serviceId());
    CallObserver o = observer;
    if (hooks == null && o == null && call.context() == CallContext.EMPTY) {
      return next.proceed(call);
    }
    return around(call, next, hooks, o);
  }

  private Object around(Invocation call, Next next, OnTarget hooks, CallObserver o)
      throws TRADEException {
    CallContext path = HookPath.only(call.context());
    String value = path == null ? null : path.get(HookPath.KEY);
    CallContext outer = path == null ? null : HookPath.enter(path);
    try {
      if (hooks != null) {
        for (Hook h : hooks.before()) {
          if (!HookPath.holds(value, h.key)) {
            callSync(h, call, value, new Object[] {arrayOf(call, 1)});
          }
        }
      }
      long started = o == null ? 0 : start(o, call);
      boolean timed = hooks != null && hooks.timed();
      long begun = timed ? System.nanoTime() : 0;
      Object result = null;
      TRADEException failure = null;
      try {
        result = next.proceed(call);
      } catch (TRADEException e) {
        failure = e;
      } catch (RuntimeException | Error e) {
        if (o != null) {
          end(o, call, started, e);
        }
        throw e;
      }
      if (o != null) {
        end(o, call, started, failure);
      }
      if (hooks != null) {
        Map<String, Object> details = timed ? details(call, System.nanoTime() - begun) : null;
        for (Hook h : hooks.after()) {
          if (!HookPath.holds(value, h.key)) {
            Object[] array = arrayOf(call, 2);
            array[array.length - 1] = failure == null ? result : null;
            Object[] args = argumentsOf(h, array, failure, details);
            if (h.kind == Kind.AFTER_ASYNC) {
              callAsync(h, call, value, args);
            } else {
              callSync(h, call, value, args);
            }
          }
        }
      }
      if (failure != null) {
        throw failure;
      }
      return result;
    } finally {
      if (path != null) {
        HookPath.exit(outer);
      }
    }
  }

  /** {@code [serviceName, args...]} and {@code extra - 1} more slots: the hook's own array. */
  private static Object[] arrayOf(Invocation call, int extra) {
    Object[] args = call.args();
    Object[] array = new Object[args.length + extra];
    array[0] = call.service().name();
    System.arraycopy(args, 0, array, 1, args.length);
    return array;
  }

  /** What the wrapper takes: the array, the failure, the details (docs/hooks.md). */
  private static Object[] argumentsOf(Hook h, Object[] array, Throwable failure,
      Map<String, Object> details) {
    return h.parameters == 1 ? new Object[] {array} : h.parameters == 2
        ? new Object[] {array, failure} : new Object[] {array, failure, details};
  }

  /** The details an after wrapper of three parameters gets; docs/hooks.md names the keys. */
  private static Map<String, Object> details(Invocation call, long nanos) {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("time", System.currentTimeMillis());
    m.put("caller", call.caller().container().toString());
    m.put("provider", call.service().containerId());
    m.put("providerName", call.service().containerName());
    m.put("service", call.service().signature());
    m.put("nanos", nanos);
    return Collections.unmodifiableMap(m); // shared by the call's wrappers

  }

  private void callSync(Hook h, Invocation call, String path, Object[] args) {
    CallContext inside = path == null ? h.solo : HookPath.inside(path, h.key);
    if (inside == null) {
      failed(h, call, "the call's hook path is too long to add its wrapper");
      return;
    }
    long timeout = Math.min(timeoutNanos, call.remainingNanos());
    if (timeout <= 0) {
      failed(h, call, "the call's deadline passed");
      return;
    }
    String from = call.caller().container().toString();
    if (!isLocal(h)) {
      run(h, from, inside, args, timeout); // the remote call gives up at its deadline
      return;
    }
    try {
      if (!local.run(() -> run(h, from, inside, args, timeout), timeout)) {
        failed(h, from, "its wrapper did not end within " + TimeUnit.NANOSECONDS.toMillis(timeout)
            + " ms (HOOKTIMEOUT, or the call's deadline); it goes on, on a thread of its own");
      }
    } catch (RejectedExecutionException e) {
      failed(h, from, "not called: " + LocalWrappers.MAX_THREADS + " local wrappers run or hang"
          + " already, or the container is closing");
    }
  }

  private void callAsync(Hook h, Invocation call, String path, Object[] args) {
    CallContext inside = path == null ? h.solo : HookPath.inside(path, h.key);
    if (inside == null) {
      failed(h, call, "the call's hook path is too long to add its wrapper");
      return;
    }
    String from = call.caller().container().toString();
    try {
      pool().execute(() -> run(h, from, inside, args, timeoutNanos));
    } catch (RejectedExecutionException e) {
      failed(h, from, "dropped: the asynchronous hooks' queue of " + QUEUE + " is full"
          + " or the container is closing");
    }
  }

  private void run(Hook h, String from, CallContext inside, Object[] args, long timeout) {
    CallContext outer = HookPath.enter(inside);
    try {
      if (h.kind == Kind.AFTER_ASYNC && !isLocal(h)) {
        // As a call whose reply nobody waits for on a link: its link goes on being read by its
        // own thread, not lent to this one, and the next call of the target's callers, coming
        // over that link, need not wait for the lending to end (docs/benchmarks.md, "Hooks").
        awaited(caller.callAsync(h.wrapper, Object.class, args, timeout));
      } else {
        caller.call(h.wrapper, Object.class, args, timeout);
      }
      h.calls.increment();
    } catch (TRADEServiceUnavailableException e) {
      // The wrapper left, or its container cannot be reached: when it left, the hook is removed
      // and that is logged once; until then, only counted.
      h.calls.increment();
      h.failures.increment();
      LOG.log(Level.DEBUG, "{0} failed on a call from container {1}: {2}", h, from, e.getMessage());
    } catch (TRADEException | RuntimeException e) {
      h.calls.increment();
      failed(h, from, e.getClass().getSimpleName() + ": " + e.getMessage());
    } finally {
      HookPath.exit(outer);
    }
  }

  private boolean isLocal(Hook h) {
    return h.wrapper.containerId().equals(caller.containerId());
  }

  /** The result of an asynchronous call, or the {@code TRADEException} it failed with. */
  private static void awaited(CompletableFuture<Object> call) throws TRADEException {
    try {
      call.join();
    } catch (CompletionException e) {
      if (e.getCause() instanceof TRADEException t) {
        throw t;
      }
      throw e;
    }
  }

  private void failed(Hook h, Invocation call, String why) {
    failed(h, call.caller().container().toString(), why);
  }

  private void failed(Hook h, String from, String why) {
    h.failures.increment();
    boolean first = h.warned.compareAndSet(false, true);
    LOG.log(first ? Level.WARNING : Level.DEBUG, "{0} failed on a call from container {1}: {2};"
        + " the call went on{3}", h, from, why,
        first ? " (later failures of this hook are logged at DEBUG and counted)" : "");
  }

  private static long start(CallObserver o, Invocation call) {
    try {
      return o.start(call);
    } catch (RuntimeException e) {
      return 0;
    }
  }

  private static void end(CallObserver o, Invocation call, long started, Throwable failure) {
    try {
      o.end(call, started, failure);
    } catch (RuntimeException e) {
      // An observer must not throw; if it does, the call's outcome is what counts.
    }
  }

  private synchronized ExecutorService pool() {
    if (closed) {
      throw new RejectedExecutionException("closed");
    }
    if (pool == null) {
      AtomicInteger n = new AtomicInteger();
      ThreadPoolExecutor p = new ThreadPoolExecutor(2, 2, 30, TimeUnit.SECONDS,
          new LinkedBlockingQueue<>(QUEUE), r -> {
            Thread t = new Thread(r, "trade-hooks-" + name + "-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
          });
      p.allowCoreThreadTimeOut(true);
      pool = p;
    }
    return pool;
  }

  /**
   * Stops the asynchronous hooks' pool (hook calls queued are dropped) and the local wrappers'
   * (those that hang keep their threads).
   */
  synchronized void close() {
    closed = true;
    local.close();
    if (pool != null) {
      pool.shutdownNow();
    }
  }
}
