package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A child JVM running a main class from the test class path, for tests that need a real second
 * process (a provider to kill with SIGKILL, values that cross a process boundary).
 *
 * <p>Its standard output is read line by line into a queue that {@link #awaitLine} consumes; its
 * standard error is copied to this JVM's standard error (prefixed with the pid) and its last lines
 * are kept for failure messages. {@link #close()} always ends the process: first by closing its
 * standard input (the programs started here exit on end of input), then forcibly. Because of that
 * contract a child also ends when this JVM dies, as its standard input then closes.
 *
 * <p>Not thread-safe: one test thread drives it; the reader threads are internal.
 */
final class JvmProcess implements AutoCloseable {
  /** Start fast and small: the children are short-lived test peers. */
  private static final List<String> JVM_OPTIONS =
      List.of("-Xshare:auto", "-XX:TieredStopAtLevel=1", "-Xmx128m");
  /** Put on the stdout queue when the child's stdout ends. */
  private static final String END = new String("<end of output>");
  private static final int STDERR_TAIL = 40;

  private final Process process;
  private final String label;
  private final BlockingQueue<String> stdout = new LinkedBlockingQueue<>();
  private final Deque<String> stderrTail = new ArrayDeque<>(); // Guarded by itself.
  private boolean outputEnded;

  private JvmProcess(Process process, String label) {
    this.process = process;
    this.label = label;
    daemon(() -> pumpStdout(process.getInputStream()), label + "-stdout").start();
    daemon(() -> pumpStderr(process.getErrorStream()), label + "-stderr").start();
  }

  /**
   * Starts {@code java -cp <this JVM's class path>[:extra...] mainClass args...}.
   *
   * @param extraClassPath entries appended to the class path (only the child sees them)
   */
  static JvmProcess start(Class<?> mainClass, List<Path> extraClassPath, String... args)
      throws IOException {
    List<String> classPath = new ArrayList<>();
    classPath.add(System.getProperty("java.class.path"));
    for (Path p : extraClassPath) {
      classPath.add(p.toString());
    }
    List<String> command = new ArrayList<>();
    command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    command.addAll(JVM_OPTIONS);
    command.add("-cp");
    command.add(String.join(File.pathSeparator, classPath));
    command.add(mainClass.getName());
    command.addAll(List.of(args));
    Process p = new ProcessBuilder(command).start();
    return new JvmProcess(p, mainClass.getSimpleName() + "-" + p.pid());
  }

  long pid() {
    return process.pid();
  }

  boolean isAlive() {
    return process.isAlive();
  }

  /**
   * Waits for the next output line that starts with {@code prefix} and returns it; lines before it
   * are skipped.
   *
   * @throws AssertionError if no such line comes within {@code timeout} or the output ends first;
   *     the message holds the child's last lines of standard error
   */
  String awaitLine(String prefix, Duration timeout) {
    long deadline = System.nanoTime() + timeout.toNanos();
    while (!outputEnded) {
      String line;
      try {
        line = stdout.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        throw new AssertionError("interrupted waiting for '" + prefix + "' from " + label, e);
      }
      if (line == null) {
        throw new AssertionError("no line starting with '" + prefix + "' from " + label + " within "
            + timeout.toMillis() + " ms" + stderrText());
      }
      if (line == END) {
        outputEnded = true;
      } else if (line.startsWith(prefix)) {
        return line;
      }
    }
    throw new AssertionError("the output of " + label + " ended before a line starting with '"
        + prefix + "'" + exitText() + stderrText());
  }

  /**
   * Kills the process with {@link Process#destroyForcibly()} and waits until it is gone. On
   * systems where {@code destroy()} is a normal termination (Linux: SIGTERM), the forcible kind is
   * SIGKILL; there this also asserts that the process died of signal 9 (exit status 128 + 9).
   */
  void kill() {
    ProcessHandle handle = process.toHandle();
    boolean signals = handle.supportsNormalTermination();
    process.destroyForcibly();
    awaitExit(Duration.ofSeconds(10));
    assertFalse(handle.isAlive(), label + " is still alive after destroyForcibly()");
    assertFalse(ProcessHandle.of(pid()).map(ProcessHandle::isAlive).orElse(false),
        label + " is still listed as alive");
    if (signals && !System.getProperty("os.name").startsWith("Windows")) {
      assertEquals(128 + 9, process.exitValue(), label + " did not die of SIGKILL");
    }
  }

  /** The process's exit status, waiting at most {@code timeout} for it to exit. */
  int awaitExit(Duration timeout) {
    try {
      assertTrue(process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS),
          label + " did not exit within " + timeout.toMillis() + " ms" + stderrText());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new AssertionError("interrupted waiting for " + label + " to exit", e);
    }
    return process.exitValue();
  }

  /** Asks the process to end (closes its input), then kills it if it is not gone within a second. */
  @Override
  public void close() {
    try {
      process.getOutputStream().close();
    } catch (IOException ignored) {
      // Already gone; the forcible path below makes sure.
    }
    try {
      if (!process.waitFor(1, TimeUnit.SECONDS)) {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      process.destroyForcibly();
      Thread.currentThread().interrupt();
    }
  }

  @Override
  public String toString() {
    return label;
  }

  private void pumpStdout(InputStream in) {
    try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
      for (String line = r.readLine(); line != null; line = r.readLine()) {
        stdout.add(line);
      }
    } catch (IOException e) {
      // The process is gone; END below tells the waiters.
    } finally {
      stdout.add(END);
    }
  }

  private void pumpStderr(InputStream in) {
    try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
      for (String line = r.readLine(); line != null; line = r.readLine()) {
        System.err.println("[" + label + "] " + line);
        synchronized (stderrTail) {
          if (stderrTail.size() == STDERR_TAIL) {
            stderrTail.removeFirst();
          }
          stderrTail.addLast(line);
        }
      }
    } catch (IOException e) {
      // The process is gone.
    }
  }

  private String exitText() {
    Optional<Integer> status = process.isAlive() ? Optional.empty() : Optional.of(process.exitValue());
    return status.map(s -> " (exit status " + s + ")").orElse("");
  }

  private String stderrText() {
    synchronized (stderrTail) {
      return stderrTail.isEmpty() ? "" : "\n  stderr of " + label + ":\n    "
          + String.join("\n    ", stderrTail);
    }
  }

  private static Thread daemon(Runnable r, String name) {
    Thread t = new Thread(r, name);
    t.setDaemon(true);
    return t;
  }
}
