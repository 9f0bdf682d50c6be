package dev.trade.internal.hooks;

import dev.trade.internal.call.CallContext;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The hooks already running on a call's path, as the reserved context key {@value #KEY} carries
 * them (docs/protocol.md, "Call context"; docs/hooks.md): the wrappers' keys,
 * {@code <container id>/<service id>}, separated by commas, outermost first.
 *
 * <p>Within one container the path follows the thread: while a service runs with a path, or a
 * hook's wrapper is being called, the thread's path is set, and every call the thread makes
 * carries it ({@link #current()}), so a hook's own calls, however deep, never run that hook again.
 * Across containers the CALL frame's context carries it. Thread confinement makes this class safe
 * for concurrent use; its static state is the per-thread path and a count of threads that hold one.
 */
public final class HookPath {
  /** The reserved call context key of the hooks running on a call's path. */
  public static final String KEY = "trade.hooks";

  private static final ThreadLocal<CallContext> CURRENT = new ThreadLocal<>();
  /**
   * Threads with a path now: while none has, {@link #current()} reads no thread-local, so a
   * container where no hook runs pays one volatile read per call for this feature.
   */
  private static final AtomicInteger HOLDERS = new AtomicInteger();

  private HookPath() {}

  /** The context of the calls this thread makes now: {@link CallContext#EMPTY} outside any hook. */
  public static CallContext current() {
    if (HOLDERS.get() == 0) {
      return CallContext.EMPTY;
    }
    CallContext c = CURRENT.get();
    return c == null ? CallContext.EMPTY : c;
  }

  /** Sets this thread's path to {@code path}'s; returns the one to give {@link #exit}. */
  static CallContext enter(CallContext path) {
    CallContext previous = CURRENT.get();
    CURRENT.set(path);
    if (previous == null) {
      HOLDERS.incrementAndGet();
    }
    return previous;
  }

  /** Restores the path {@link #enter} replaced. */
  static void exit(CallContext previous) {
    if (previous == null) {
      CURRENT.remove();
      HOLDERS.decrementAndGet();
    } else {
      CURRENT.set(previous);
    }
  }

  /** The key of a wrapper in a path. */
  static String key(String containerId, long serviceId) {
    return containerId + "/" + serviceId;
  }

  /** Whether {@code path} (a value of {@link #KEY}, or null) holds {@code key}. */
  static boolean holds(String path, String key) {
    if (path == null) {
      return false;
    }
    int from = 0;
    while (true) {
      int at = path.indexOf(key, from);
      if (at < 0) {
        return false;
      }
      int end = at + key.length();
      if ((at == 0 || path.charAt(at - 1) == ',') && (end == path.length()
          || path.charAt(end) == ',')) {
        return true;
      }
      from = at + 1;
    }
  }

  /**
   * The context of a call made inside hook {@code key} on a call with path {@code path}, or null
   * when the path would no longer fit a context value ({@link CallContext#MAX_VALUE} bytes).
   */
  static CallContext inside(String path, String key) {
    String value = path == null ? key : path + "," + key;
    if (value.getBytes(StandardCharsets.UTF_8).length > CallContext.MAX_VALUE) {
      return null;
    }
    return CallContext.of(Map.of(KEY, value));
  }

  /** The context holding only the path of {@code context}, or null when it has none. */
  static CallContext only(CallContext context) {
    String path = context.get(KEY);
    if (path == null) {
      return null;
    }
    return context.entries().size() == 1 ? context : CallContext.of(Map.of(KEY, path));
  }
}
