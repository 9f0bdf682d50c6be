package dev.trade.examples;

import java.io.File;
import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/** Starting example programs in JVMs of their own, as a user would, for tests. */
public final class Jvms {
  private Jvms() {}

  /** The directory holding {@code config/demo.launch}: the working directory or a parent. */
  public static Path projectRoot() {
    for (Path p = Path.of("").toAbsolutePath(); p != null; p = p.getParent()) {
      if (Files.isRegularFile(p.resolve("config/demo.launch"))) {
        return p;
      }
    }
    throw new AssertionError("no config/demo.launch above " + Path.of("").toAbsolutePath());
  }

  /** A class path holding the given classes (their class directories or jars). */
  public static String classpathOf(Class<?>... classes) {
    Set<String> entries = new LinkedHashSet<>();
    for (Class<?> c : classes) {
      try {
        entries.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
      } catch (URISyntaxException e) {
        throw new AssertionError(e);
      }
    }
    return String.join(File.pathSeparator, entries);
  }

  /**
   * Starts {@code java -cp CLASSPATH MAIN ARGS} with stderr merged into stdout and stdin closed.
   */
  public static Process start(String classpath, Class<?> main, String... args) throws IOException {
    List<String> command = new ArrayList<>(List.of(
        Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", classpath,
        main.getName()));
    command.addAll(List.of(args));
    Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
    p.getOutputStream().close();
    return p;
  }

  /** Kills {@code p} and its descendants if still running (test cleanup). */
  public static void kill(Process p) {
    if (p != null && p.isAlive()) {
      p.descendants().forEach(ProcessHandle::destroyForcibly);
      p.destroyForcibly();
    }
  }
}
