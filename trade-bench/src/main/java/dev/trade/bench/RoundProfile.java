package dev.trade.bench;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import javax.management.JMException;
import javax.management.ObjectName;

/**
 * A CPU profile of one scale JVM in a round, from GO until its containers converged, by
 * async-profiler (not part of this project: give the path of its {@code libasyncProfiler.so} as
 * {@code -Dbench.scaleProfiler=<path>}, and where to write as {@code -Dbench.scaleProfiles=<dir>};
 * for one JVM of the scale part, pass both in {@code -Dbench.nodeOptions}). It takes a sample
 * for every 2 ms of CPU the JVM uses, on whichever thread, JIT compiler and collector threads
 * included, and marks each Java frame interpreted, C1 or C2 compiled;
 * {@code trade-bench/src/main/python/frame_types.py} counts them (docs/benchmarks-log.md, "What
 * the cold third is"). The JDK's flight recorder does not tell C1
 * from C2, and at a 2 ms period it recorded 45 samples of a 25-container JVM in a 10 s round.
 * The profiler is loaded as an agent through the JVM's diagnostic command, so that it needs no
 * jar on the class path, and logs to {@code profiler.log} in that directory, not to standard
 * output, which is this JVM's channel to the benchmark. The profile costs CPU of its own; the
 * published figures are made without it. Used by the scale JVM's main thread only.
 */
final class RoundProfile {
  private static final String LIBRARY = System.getProperty("bench.scaleProfiler");
  private static final Path DIRECTORY =
      Path.of(System.getProperty("bench.scaleProfiles", ".")).toAbsolutePath();
  private static int rounds;

  private RoundProfile() {}

  /** Starts profiling if asked to; returns whether it did. */
  static boolean start() throws JMException {
    if (LIBRARY == null) {
      return false;
    }
    agent("start,event=cpu,interval=2ms,cstack=vm");
    return true;
  }

  /** Stops profiling and writes {@code <dir>/<prefix>round<n>.collapsed}, frames marked by type. */
  static void save(String prefix) throws JMException {
    rounds++;
    agent("stop,collapsed,ann,file=" + DIRECTORY.resolve(prefix + "round" + rounds + ".collapsed"));
  }

  /**
   * Runs an async-profiler command; quoted, since the diagnostic command reads a=b as its own.
   *
   * @throws IllegalStateException if the library did not load or refused the command
   */
  private static void agent(String command) throws JMException {
    String options = '"' + command + ",log=" + DIRECTORY.resolve("profiler.log") + '"';
    Object out = ManagementFactory.getPlatformMBeanServer().invoke(
        new ObjectName("com.sun.management:type=DiagnosticCommand"), "jvmtiAgentLoad",
        new Object[] {new String[] {LIBRARY, options}}, new String[] {String[].class.getName()});
    if (!"return code: 0".equals(String.valueOf(out).trim())) {
      throw new IllegalStateException("async-profiler (" + LIBRARY + ", " + command + "): " + out);
    }
  }
}
