package dev.trade.testing;

import java.lang.reflect.Method;

/**
 * How many bytes of heap the current thread has allocated so far (HotSpot's per-thread counter),
 * for tests that bound what decoding hostile input may allocate. Read through reflection: the
 * tests compile against the trade module, which does not read {@code java.management}.
 */
public final class Allocations {
  private static final Object BEAN;
  private static final Method ALLOCATED;

  static {
    try {
      Class<?> factory = Class.forName("java.lang.management.ManagementFactory");
      BEAN = factory.getMethod("getThreadMXBean").invoke(null);
      ALLOCATED = Class.forName("com.sun.management.ThreadMXBean")
          .getMethod("getThreadAllocatedBytes", long.class);
    } catch (ReflectiveOperationException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  private Allocations() {}

  /** Bytes the current thread has allocated since it started. */
  public static long ofThisThread() {
    try {
      return (long) ALLOCATED.invoke(BEAN, Thread.currentThread().getId());
    } catch (ReflectiveOperationException e) {
      throw new IllegalStateException(e);
    }
  }
}
