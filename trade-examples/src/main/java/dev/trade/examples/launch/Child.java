package dev.trade.examples.launch;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One component's JVM. A pump thread prints each line of its output (stdout and stderr, merged so
 * that their order is kept) with the component's prefix, hands it to the launcher, and reports the
 * exit status once the output has ended, so that the exit is never reported before the process's
 * last line. Safe for concurrent use.
 */
final class Child {
  /** What the launcher hears from a child; called on the child's pump thread. */
  interface Listener {
    void line(Child child, String line);

    void exited(Child child, int status);
  }

  private final LaunchFile.Component spec;
  private final Process process;
  private final Thread pump;
  private volatile boolean killed;

  private Child(LaunchFile.Component spec, Process process, String prefix, PrintStream out,
      Listener listener) {
    this.spec = spec;
    this.process = process;
    this.pump = new Thread(() -> pump(prefix, out, listener), "launch-output-" + spec.name());
    pump.setDaemon(true); // never keeps the launcher alive; stop() waits for it instead
  }

  /**
   * Starts {@code command} as the process of {@code spec}.
   *
   * @throws IOException if the process cannot be started
   */
  static Child start(LaunchFile.Component spec, List<String> command, String prefix,
      PrintStream out, Listener listener) throws IOException {
    Process p = new ProcessBuilder(command).redirectErrorStream(true)
        .redirectInput(ProcessBuilder.Redirect.PIPE).start();
    // The child never reads its input; closing it at once means a read sees end-of-file, not a hang.
    p.getOutputStream().close();
    Child child = new Child(spec, p, prefix, out, listener);
    child.pump.start();
    return child;
  }

  private void pump(String prefix, PrintStream out, Listener listener) {
    // The child's output is in its default charset, which is the same as ours on one machine.
    try (BufferedReader in = new BufferedReader(
        new InputStreamReader(process.getInputStream(), Charset.defaultCharset()))) {
      String line;
      while ((line = in.readLine()) != null) {
        out.println(prefix + line);
        listener.line(this, line);
      }
    } catch (IOException e) {
      out.println(prefix + "(output lost: " + e.getMessage() + ")");
    }
    int status;
    try {
      status = process.waitFor();
    } catch (InterruptedException e) {
      return; // the launcher is going away
    }
    listener.exited(this, status);
  }

  LaunchFile.Component spec() {
    return spec;
  }

  String name() {
    return spec.name();
  }

  long pid() {
    return process.pid();
  }

  boolean isAlive() {
    return process.isAlive();
  }

  /** Whether {@link #kill()} ended it: a scripted crash, not a failure. */
  boolean wasKilled() {
    return killed;
  }

  /** Kills the process and its descendants at once (SIGKILL): no shutdown hook runs. */
  void kill() {
    killed = true;
    process.descendants().forEach(ProcessHandle::destroyForcibly);
    process.destroyForcibly();
  }

  /** Asks the process and its descendants to stop (SIGTERM): shutdown hooks run. */
  void stop() {
    process.descendants().forEach(ProcessHandle::destroy);
    process.destroy();
  }

  /** Waits until the process has ended, or {@code deadline} ({@link System#nanoTime()}) passed. */
  boolean awaitExit(long deadline) throws InterruptedException {
    return process.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
  }

  /** Waits until all of the process's output has been printed, at most until {@code deadline}. */
  void awaitOutput(long deadline) throws InterruptedException {
    pump.join(Math.max(1, TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime())));
  }
}
