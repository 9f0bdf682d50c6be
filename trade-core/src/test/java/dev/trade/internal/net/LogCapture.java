package dev.trade.internal.net;

import java.util.ArrayList;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;

/**
 * Records what the networking code logs. {@code System.Logger} maps to java.util.logging unless
 * another backend is installed, so a handler on the JUL logger {@code dev.trade.net} sees it all,
 * DEBUG included (JUL's {@code FINE}). Close it to remove the handler and restore the level.
 */
public final class LogCapture extends Handler implements AutoCloseable {
  private final Logger logger = Logger.getLogger("dev.trade.net");
  private final SimpleFormatter formatter = new SimpleFormatter();
  // Guarded by this.
  private final List<String> lines = new ArrayList<>();

  /** The logger's own level before; DEBUG lines (FINE) are only made while capturing. */
  private final Level before = logger.getLevel();

  public LogCapture() {
    setLevel(Level.ALL);
    logger.setLevel(Level.ALL);
    logger.addHandler(this);
  }

  @Override
  public void publish(LogRecord record) {
    String line = record.getLevel() + " " + formatter.formatMessage(record);
    synchronized (this) {
      lines.add(line);
    }
  }

  /** Every line so far, each as {@code LEVEL message}. */
  synchronized List<String> lines() {
    return List.copyOf(lines);
  }

  /** The last lines, for failure messages. */
  public String tail() {
    List<String> all = lines();
    return String.join("\n", all.subList(Math.max(0, all.size() - 12), all.size()));
  }

  /** Whether some line of {@code level} contains every one of {@code parts}. */
  public boolean has(Level level, String... parts) {
    for (String line : lines()) {
      if (line.startsWith(level + " ") && containsAll(line, parts)) {
        return true;
      }
    }
    return false;
  }

  private static boolean containsAll(String line, String... parts) {
    for (String p : parts) {
      if (!line.contains(p)) {
        return false;
      }
    }
    return true;
  }

  @Override
  public void flush() {}

  @Override
  public void close() {
    logger.removeHandler(this);
    logger.setLevel(before);
  }
}
