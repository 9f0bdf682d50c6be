package dev.trade.examples.launch;

import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Starts the components of a {@link LaunchFile}, each in a JVM of its own, prints their output
 * with their names in front ({@code [arm] opening gripper}), kills the ones the file says to kill,
 * and stops them all when the launch ends, when its deadline passes, or on Ctrl-C:
 *
 * <pre>
 * java -cp CLASSPATH dev.trade.examples.launch.Launcher [--set KEY=VALUE]... [--classpath CP]... LAUNCH-FILE
 * </pre>
 *
 * Every component runs {@code java [java-options] -cp CLASSPATH [-Dtrade.properties.path=FILE]
 * MAIN-CLASS ARGUMENTS}, where CLASSPATH is this JVM's class path (TRADE itself), then the
 * entries given with {@code --classpath} (your components), then those of the launch file's
 * {@code classpath} directive. {@code --set} overrides a key of the launch
 * file's {@code properties} (for example a {@code TRADESYSID} of its own for a test run).
 *
 * <p>The launch ends when a component marked {@code exit} exits, or when nothing runs any more and
 * nothing is waiting to start. Exit status: that component's status when it is non-zero; else 1
 * if the deadline passed, a component could not start, or another one ended with a non-zero
 * status of its own accord (a scripted kill is not a failure); else 0. Status 2: bad arguments or
 * launch file.
 *
 * <p>All decisions are taken on the thread that calls {@link #run()}; output threads and timers
 * only queue events for it. {@link #stopAll()} may be called from any thread.
 */
public final class Launcher {
  private static final String USAGE =
      "usage: Launcher [--set KEY=VALUE]... [--classpath CLASSPATH]... LAUNCH-FILE";
  private static final Duration STOP_GRACE = Duration.ofSeconds(5);

  private final LaunchFile launch;
  private final List<String> jvm;
  private final PrintStream out;
  private final int width;
  private final BlockingQueue<Runnable> events = new LinkedBlockingQueue<>();
  private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(r -> {
    Thread t = new Thread(r, "launch-timer");
    t.setDaemon(true);
    return t;
  });
  private final Map<String, Child> children = new LinkedHashMap<>(); // Guarded by this.
  private boolean stopped; // Guarded by this.

  // Owned by the run() thread.
  private final Set<String> begun = new HashSet<>();
  private final Set<String> running = new HashSet<>();
  private final Set<String> killDue = new HashSet<>();
  private int startsScheduled;
  private boolean failed;
  private Integer result;

  /**
   * @param classpath the class path of every component's JVM
   * @param properties the trade.properties to give every component, or null
   */
  public Launcher(LaunchFile launch, String classpath, Path properties, PrintStream out) {
    this.launch = launch;
    this.out = out;
    this.jvm = new ArrayList<>();
    jvm.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
    jvm.addAll(launch.javaOptions());
    jvm.add("-cp");
    jvm.add(classpath);
    if (properties != null) {
      jvm.add("-Dtrade.properties.path=" + properties.toAbsolutePath());
    }
    int w = "launch".length();
    for (LaunchFile.Component c : launch.components()) {
      w = Math.max(w, c.name().length());
    }
    this.width = w + 2;
  }

  public static void main(String[] args) throws InterruptedException {
    Map<String, String> overrides = new LinkedHashMap<>();
    List<String> classPath = new ArrayList<>();
    Path file = null;
    LaunchFile launch;
    Path properties;
    try {
      for (int i = 0; i < args.length; i++) {
        if (args[i].equals("--set") && i + 1 < args.length && args[i + 1].indexOf('=') > 0) {
          String kv = args[++i];
          overrides.put(kv.substring(0, kv.indexOf('=')), kv.substring(kv.indexOf('=') + 1));
        } else if ((args[i].equals("--classpath") || args[i].equals("-cp")) && i + 1 < args.length) {
          classPath.add(args[++i]);
        } else if (args[i].startsWith("-") || file != null) {
          throw new IllegalArgumentException(USAGE);
        } else {
          file = Path.of(args[i]);
        }
      }
      if (file == null) {
        throw new IllegalArgumentException(USAGE);
      }
      launch = LaunchFile.read(file);
      properties = withOverrides(launch.properties(), overrides);
    } catch (IOException | IllegalArgumentException e) {
      System.err.println("launch: " + e.getMessage());
      System.exit(2);
      return;
    }
    Launcher launcher = new Launcher(launch,
        classPath(System.getProperty("java.class.path"), classPath, launch), properties, System.out);
    // Ctrl-C and kill stop the components too; after a normal end this finds nothing to stop.
    Runtime.getRuntime().addShutdownHook(new Thread(launcher::stopAll, "launch-shutdown"));
    System.exit(launcher.run());
  }

  /**
   * The components' class path: the launcher's own (TRADE), then the command line's, then the
   * launch file's entries.
   */
  static String classPath(String own, List<String> given, LaunchFile launch) {
    List<String> all = new ArrayList<>();
    all.add(own);
    all.addAll(given);
    all.addAll(launch.classPath());
    return String.join(File.pathSeparator, all);
  }

  /** {@code properties} with {@code overrides} applied, in a temporary file; or as it is. */
  private static Path withOverrides(Path properties, Map<String, String> overrides) throws IOException {
    if (overrides.isEmpty()) {
      return properties;
    }
    Properties p = new Properties();
    if (properties != null) {
      try (Reader r = Files.newBufferedReader(properties, StandardCharsets.UTF_8)) {
        p.load(r);
      }
    }
    p.putAll(overrides);
    Path merged = Files.createTempFile("trade-launch-", ".properties");
    merged.toFile().deleteOnExit();
    try (Writer w = Files.newBufferedWriter(merged, StandardCharsets.UTF_8)) {
      p.store(w, "from " + properties + " with " + overrides.keySet());
    }
    return merged;
  }

  /**
   * Runs the launch until it ends (see the class comment), then stops every component still
   * running.
   *
   * @return the exit status
   */
  public int run() throws InterruptedException {
    long start = System.nanoTime();
    Duration deadline = launch.deadline();
    say(launch.file().getFileName() + ": " + launch.components().size() + " components"
        + (deadline == null ? "" : ", deadline " + seconds(deadline.toNanos())));
    try {
      for (LaunchFile.Component c : launch.components()) {
        if (c.after() == null) {
          schedule(c);
        }
      }
      idleCheck();
      while (result == null && !isStopped()) {
        Runnable event = deadline == null ? events.take()
            : events.poll(start + deadline.toNanos() - System.nanoTime(), TimeUnit.NANOSECONDS);
        if (event == null) {
          say("deadline of " + seconds(deadline.toNanos()) + " passed");
          result = 1;
          break;
        }
        event.run();
        idleCheck();
      }
    } finally {
      stopAll();
      timer.shutdownNow();
    }
    if (result == null) {
      result = 1; // stopped from outside: Ctrl-C or a signal
    }
    say("done in " + seconds(System.nanoTime() - start) + ", exit status " + result);
    return result;
  }

  /** Starts {@code c} after its delay. */
  private void schedule(LaunchFile.Component c) {
    begun.add(c.name());
    startsScheduled++;
    if (c.delay().isZero()) {
      start(c);
    } else {
      timer.schedule(() -> events.add(() -> start(c)), c.delay().toNanos(), TimeUnit.NANOSECONDS);
    }
  }

  private void start(LaunchFile.Component c) {
    startsScheduled--;
    if (result != null) {
      return;
    }
    List<String> command = new ArrayList<>(jvm);
    command.add(c.mainClass());
    command.addAll(c.arguments());
    Child child;
    synchronized (this) {
      if (stopped) {
        return;
      }
      try {
        child = Child.start(c, command, prefix(c.name()), out, new Child.Listener() {
          @Override
          public void line(Child from, String line) {
            events.add(() -> onLine(from, line));
          }

          @Override
          public void exited(Child from, int status) {
            events.add(() -> onExit(from, status));
          }
        });
      } catch (IOException e) {
        say("cannot start " + c.name() + ": " + e.getMessage());
        result = 1;
        return;
      }
      children.put(c.name(), child);
    }
    running.add(c.name());
    say("started " + c.name() + (c.after() == null ? "" : " (after " + c.after() + ")")
        + ", pid " + child.pid());
    for (LaunchFile.Component d : launch.components()) {
      if (!begun.contains(d.name()) && d.after() != null && d.after().text() == null
          && d.after().component().equals(c.name())) {
        schedule(d);
      }
    }
    if (c.killAfter() != null) {
      timer.schedule(() -> events.add(() -> kill(c.name())), c.killAfter().toNanos(),
          TimeUnit.NANOSECONDS);
    }
    if (killDue.contains(c.name())) {
      kill(c.name());
    }
  }

  private void onLine(Child from, String line) {
    for (LaunchFile.Component d : launch.components()) {
      if (d.after() != null && !begun.contains(d.name()) && d.after().matches(from.name(), line)) {
        schedule(d);
      }
      if (d.killWhen() != null && d.killWhen().matches(from.name(), line) && killDue.add(d.name())
          && running.contains(d.name())) {
        kill(d.name());
      }
    }
  }

  private void kill(String name) {
    Child child;
    synchronized (this) {
      child = children.get(name);
    }
    if (child != null && running.contains(name) && !child.wasKilled()) {
      say("killing " + name + " (SIGKILL)");
      child.kill();
    }
  }

  private void onExit(Child child, int status) {
    running.remove(child.name());
    if (isStopped()) {
      return; // stopAll() ended it
    }
    if (child.wasKilled()) {
      say(child.name() + " is gone (killed)");
      return;
    }
    say(child.name() + " exited with status " + status);
    if (child.spec().exit()) {
      result = status != 0 ? status : failed ? 1 : 0;
    } else if (status != 0) {
      failed = true;
    }
  }

  /** Ends the launch when nothing runs and nothing will start. */
  private void idleCheck() {
    if (result != null || !running.isEmpty() || startsScheduled > 0) {
      return;
    }
    List<String> never = new ArrayList<>();
    for (LaunchFile.Component c : launch.components()) {
      if (!begun.contains(c.name())) {
        never.add(c.name() + " (waits until " + c.after() + ")");
      }
    }
    if (!never.isEmpty()) {
      say("nothing runs any more, and these never started: " + String.join(", ", never));
    }
    result = failed || !never.isEmpty() ? 1 : 0;
  }

  /**
   * Stops every component still running: SIGTERM to it and its descendants, and SIGKILL to those
   * still there after 5 s; then waits briefly for their last output. Idempotent; any thread.
   */
  public void stopAll() {
    List<Child> alive = new ArrayList<>();
    synchronized (this) {
      if (stopped) {
        return;
      }
      stopped = true;
      for (Child c : children.values()) {
        if (c.isAlive()) {
          alive.add(c);
        }
      }
    }
    try {
      if (!alive.isEmpty()) {
        List<String> names = new ArrayList<>();
        alive.forEach(c -> names.add(c.name()));
        say("stopping " + String.join(", ", names));
        alive.forEach(Child::stop);
        long deadline = System.nanoTime() + STOP_GRACE.toNanos();
        for (Child c : alive) {
          if (!c.awaitExit(deadline)) {
            say(c.name() + " did not stop within " + seconds(STOP_GRACE.toNanos()) + "; killing it");
            c.kill();
          }
        }
      }
      long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(1);
      List<Child> all;
      synchronized (this) {
        all = new ArrayList<>(children.values());
      }
      for (Child c : all) {
        c.awaitOutput(deadline);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      synchronized (this) {
        children.values().forEach(Child::kill);
      }
    }
  }

  private synchronized boolean isStopped() {
    return stopped;
  }

  private String prefix(String name) {
    return String.format(Locale.ROOT, "%-" + width + "s ", "[" + name + "]");
  }

  private void say(String text) {
    out.println(prefix("launch") + text);
  }

  private static String seconds(long nanos) {
    return String.format(Locale.ROOT, "%.1f s", nanos / 1e9);
  }
}
