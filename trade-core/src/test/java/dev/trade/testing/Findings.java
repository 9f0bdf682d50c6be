package dev.trade.testing;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What a fuzz target found: inputs that ended in anything but a value or the typed refusal the
 * target allows, and exceptions uncaught on any thread while it ran. Thread-safe.
 */
public final class Findings implements AutoCloseable {
  /** Enough to read the first few; the count says how many there were. */
  private static final int KEPT = 20;

  private final String target;
  private final List<String> kept = new CopyOnWriteArrayList<>();
  private final AtomicLong count = new AtomicLong();
  private final Thread.UncaughtExceptionHandler previous;

  /**
   * Starts recording for {@code target}; exceptions uncaught on any thread are findings from now
   * until {@link #close}.
   */
  public Findings(String target) {
    this.target = target;
    this.previous = Thread.getDefaultUncaughtExceptionHandler();
    Thread.setDefaultUncaughtExceptionHandler((t, e) -> add("uncaught on thread " + t.getName(), e));
  }

  /** Records an input that ended in {@code e}. */
  public void add(byte[] input, Throwable e) {
    add("input " + Mutator.hex(input), e);
  }

  /** Records a finding described by {@code what}. */
  public void add(String what, Throwable e) {
    if (count.incrementAndGet() <= KEPT) {
      StringBuilder s = new StringBuilder(what).append("\n    ").append(e);
      for (StackTraceElement f : e.getStackTrace()) {
        if (s.length() > 4000) {
          break;
        }
        s.append("\n      at ").append(f);
      }
      kept.add(s.toString());
    }
  }

  public long count() {
    return count.get();
  }

  /** @throws AssertionError listing the first findings, if there were any */
  public void assertNone() {
    if (count.get() > 0) {
      throw new AssertionError(target + ": " + count.get() + " findings (seed " + Mutator.seed()
          + "); the first:\n" + String.join("\n", kept));
    }
  }

  /** Prints one line of figures for docs/reliability.md and the log of a run. */
  public void report(String figures) {
    System.out.printf("fuzz %s: seed=%d %s findings=%d%n", target, Mutator.seed(), figures, count.get());
  }

  @Override
  public void close() {
    Thread.setDefaultUncaughtExceptionHandler(previous);
  }
}
