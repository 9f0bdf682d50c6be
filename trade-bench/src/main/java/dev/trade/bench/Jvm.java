package dev.trade.bench;

import dev.trade.TRADEContainer;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A child JVM, on this JVM's class path or on a TRADE application's ({@link #tradeClassPath}). Its
 * standard output is read line by line ({@link #await}); its standard error goes to a log file;
 * closing its standard input ({@link #close}) tells the bench mains to exit, and a child still
 * alive a few seconds later is killed.
 */
final class Jvm implements AutoCloseable {
  private final Process process;
  private final BlockingQueue<String> lines = new LinkedBlockingQueue<>();
  private final OutputStream stdin;
  final long spawnedEpochMicros;

  private Jvm(Process process, long spawnedEpochMicros) {
    this.process = process;
    this.spawnedEpochMicros = spawnedEpochMicros;
    this.stdin = process.getOutputStream();
    Thread reader = new Thread(() -> {
      try (BufferedReader r = new BufferedReader(
          new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
        for (String line; (line = r.readLine()) != null; ) {
          lines.add(line);
        }
      } catch (IOException ignored) {
        // The child is gone.
      }
      lines.add("EOF");
    }, "jvm-out-" + process.pid());
    reader.setDaemon(true);
    reader.start();
  }

  /** Starts {@code mainClass} with {@code jvmOptions} and {@code args}; stderr goes to {@code log}. */
  static Jvm start(List<String> jvmOptions, Class<?> mainClass, Path log, String... args)
      throws IOException {
    return start(System.getProperty("java.class.path"), jvmOptions, mainClass, log, args);
  }

  /**
   * The class path of a TRADE application: trade-core and this module's classes, without the peers'
   * jars this module also carries (gRPC with Netty, Guava, JGroups, JMH: 21 MB). A JVM's start looks
   * up services (logging, security providers) in every jar on its class path, opening and indexing
   * each: with those jars a provider's start → callable took 25 ms longer (median of 24 pairs).
   */
  static String tradeClassPath() {
    return codeSource(Jvm.class) + File.pathSeparator + codeSource(TRADEContainer.class);
  }

  private static String codeSource(Class<?> c) {
    try {
      return Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
    } catch (URISyntaxException e) {
      throw new IllegalStateException(e);
    }
  }

  /** As {@link #start(List, Class, Path, String...)}, on another class path. */
  static Jvm start(String classPath, List<String> jvmOptions, Class<?> mainClass, Path log,
      String... args) throws IOException {
    List<String> cmd = new ArrayList<>();
    cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    cmd.add("-cp");
    cmd.add(classPath);
    cmd.add("-Djava.net.preferIPv4Stack=true");
    cmd.addAll(jvmOptions);
    cmd.add(mainClass.getName());
    cmd.addAll(List.of(args));
    ProcessBuilder pb = new ProcessBuilder(cmd);
    File logFile = log.toFile();
    logFile.getParentFile().mkdirs();
    pb.redirectError(ProcessBuilder.Redirect.appendTo(logFile));
    long now = Clock.epochMicros();
    return new Jvm(pb.start(), now);
  }

  /** The next line that starts with {@code prefix} (earlier lines are skipped). */
  String await(String prefix, long timeoutMs) throws IOException, InterruptedException {
    long until = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
    while (true) {
      String line = lines.poll(Math.max(1, until - System.nanoTime()), TimeUnit.NANOSECONDS);
      if (line == null) {
        throw new IOException("child " + process.pid() + " did not print '" + prefix + "' within "
            + timeoutMs + " ms");
      }
      if (line.equals("EOF")) {
        lines.add(line); // for the next await too, which would otherwise wait out its timeout
        throw new IOException("child " + process.pid() + " exited before printing '" + prefix + "'");
      }
      if (line.startsWith(prefix)) {
        return line.substring(prefix.length()).trim();
      }
    }
  }

  /** Sends one line to the child's standard input. */
  void send(String line) throws IOException {
    stdin.write((line + "\n").getBytes(StandardCharsets.UTF_8));
    stdin.flush();
  }

  long pid() {
    return process.pid();
  }

  /** kill -9. */
  void kill() {
    process.destroyForcibly();
  }

  @Override
  public void close() throws InterruptedException {
    try {
      stdin.close();
    } catch (IOException ignored) {
      // Already gone.
    }
    if (!process.waitFor(10, TimeUnit.SECONDS)) {
      process.destroyForcibly();
      process.waitFor(5, TimeUnit.SECONDS);
    }
  }
}
