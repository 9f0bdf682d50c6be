package dev.trade.examples;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.Charset;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * The output of a launcher process, read as it comes, for tests that wait for lines with a
 * deadline instead of sleeping. Lines are kept as printed, with the prefix padding squeezed to one
 * blank ({@code [arm] opening gripper}). Safe for concurrent use.
 */
public final class Transcript {
  private final List<String> lines = new ArrayList<>(); // Guarded by this.
  private final Map<String, Integer> cursors = new HashMap<>(); // Guarded by this.
  private boolean ended; // Guarded by this.

  /** Starts reading {@code in} on a daemon thread. */
  public Transcript(InputStream in) {
    Thread reader = new Thread(() -> read(in), "transcript-reader");
    reader.setDaemon(true);
    reader.start();
  }

  private void read(InputStream in) {
    try (BufferedReader r = new BufferedReader(new InputStreamReader(in, Charset.defaultCharset()))) {
      String line;
      while ((line = r.readLine()) != null) {
        String squeezed = line.replaceFirst("^(\\[[^\\]]+\\]) +", "$1 ");
        synchronized (this) {
          lines.add(squeezed);
          notifyAll();
        }
      }
    } catch (IOException e) {
      // The process went away; what was read is kept.
    } finally {
      synchronized (this) {
        ended = true;
        notifyAll();
      }
    }
  }

  /**
   * Waits for the next line of {@code component} (after the one the previous call for it found)
   * that contains {@code text}, and returns it. A null {@code component} means any line: for the
   * output of a single program.
   *
   * @param deadline a {@link System#nanoTime()} value
   * @throws AssertionError at the deadline or when the output ended, with the whole transcript
   */
  public synchronized String await(String component, String text, long deadline)
      throws InterruptedException {
    String prefix = component == null ? "" : "[" + component + "] ";
    while (true) {
      for (int i = cursors.getOrDefault(component, 0); i < lines.size(); i++) {
        if (lines.get(i).startsWith(prefix) && lines.get(i).contains(text)) {
          cursors.put(component, i + 1);
          return lines.get(i);
        }
      }
      long remaining = deadline - System.nanoTime();
      if (ended || remaining <= 0) {
        throw new AssertionError((ended ? "output ended" : "deadline passed") + " before a line "
            + prefix + "..." + text + "...\n" + this);
      }
      TimeUnit.NANOSECONDS.timedWait(this, remaining);
    }
  }

  /** Whether some line of {@code component} so far contains {@code text}. */
  public synchronized boolean contains(String component, String text) {
    String prefix = component == null ? "" : "[" + component + "] ";
    for (String line : lines) {
      if (line.startsWith(prefix) && line.contains(text)) {
        return true;
      }
    }
    return false;
  }

  /** Every line so far. */
  @Override
  public synchronized String toString() {
    return "--- transcript ---\n" + String.join("\n", lines) + "\n---";
  }
}
