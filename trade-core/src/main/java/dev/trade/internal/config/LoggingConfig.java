package dev.trade.internal.config;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.lang.System.Logger.Level;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;
import java.util.logging.LogManager;

/**
 * TRADE's logging configuration file: a {@code java.util.logging} properties file named by the
 * system property {@value #PATH_PROPERTY}, else the environment variable {@value #PATH_ENV}, else
 * {@value #FILE} in the working directory if there is one. Its entries are merged into the JVM's
 * logging configuration (keys it does not set keep their values), once per file and JVM.
 * Thread-safe.
 */
public final class LoggingConfig {
  /** System property naming the logging file. */
  public static final String PATH_PROPERTY = "tradeLogging.config.path";
  /** Environment variable naming the logging file. */
  public static final String PATH_ENV = "TRADE_LOGGING_CONFIG_PATH";
  /** File looked for in the working directory when neither names one. */
  public static final String FILE = "tradeLogging.config";

  private static final System.Logger LOG = System.getLogger(Settings.class.getName());
  /** The file applied last: a container built again from the same configuration does not re-read it. */
  private static final AtomicReference<Path> APPLIED = new AtomicReference<>();

  private LoggingConfig() {}

  /** Applies the file the real system property, environment and working directory name. */
  public static void apply() {
    apply(System::getProperty, System::getenv, Path.of(""));
  }

  /**
   * Applies the logging file these sources name, if any.
   *
   * @return the file applied now, or null (none named or present, or applied before)
   * @throws IllegalArgumentException if a named file does not exist, naming it and its source
   * @throws UncheckedIOException if the file cannot be read
   */
  static Path apply(Function<String, String> systemProperties, Function<String, String> environment,
      Path workingDirectory) {
    Objects.requireNonNull(workingDirectory, "workingDirectory == null");
    String property = blankToNull(systemProperties.apply(PATH_PROPERTY));
    String env = blankToNull(environment.apply(PATH_ENV));
    Path file;
    if (property != null || env != null) {
      String origin = property != null ? "system property " + PATH_PROPERTY
          : "environment variable " + PATH_ENV;
      String text = property != null ? property : env;
      try {
        file = Path.of(text);
      } catch (InvalidPathException e) {
        throw new IllegalArgumentException(origin + "=" + text + ": not a valid path", e);
      }
      if (!Files.isRegularFile(file)) {
        throw new IllegalArgumentException(origin + "=" + text + ": "
            + (Files.exists(file) ? "not a regular file" : "no such file") + " ("
            + file.toAbsolutePath() + ")");
      }
    } else {
      file = workingDirectory.resolve(FILE);
      if (!Files.isRegularFile(file)) {
        return null;
      }
    }
    Path absolute = file.toAbsolutePath().normalize();
    if (absolute.equals(APPLIED.getAndSet(absolute))) {
      return null;
    }
    try (InputStream in = Files.newInputStream(file)) {
      // Merge: what the file leaves out keeps the JVM's own setting.
      LogManager.getLogManager().updateConfiguration(in,
          key -> (old, given) -> given != null ? given : old);
    } catch (IOException e) {
      APPLIED.compareAndSet(absolute, null);
      throw new UncheckedIOException("cannot read logging configuration " + absolute, e);
    }
    LOG.log(Level.DEBUG, "logging configured from {0}", absolute);
    return absolute;
  }

  private static String blankToNull(String s) {
    return s == null || s.isBlank() ? null : s.trim();
  }
}
