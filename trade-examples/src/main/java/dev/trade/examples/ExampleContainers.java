package dev.trade.examples;

import dev.trade.TRADEContainer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.logging.Level;
import java.util.logging.Logger;

/**
 * How the example programs make their container: from a {@code trade.properties} file, with a
 * name of their own, and with TRADE's logging turned down so that transcripts stay readable.
 */
public final class ExampleContainers {
  private static final String PATH_PROPERTY = "trade.properties.path";

  private ExampleContainers() {}

  /**
   * Shows only warnings and errors, each on one line, unless {@code verbose}; then TRADE's INFO
   * lines too (links, discovery). Call it first in {@code main}, before anything logs.
   */
  public static void configureLogging(boolean verbose) {
    // SimpleFormatter reads this once, when the first log record is formatted.
    if (System.getProperty("java.util.logging.SimpleFormatter.format") == null) {
      System.setProperty("java.util.logging.SimpleFormatter.format", "%4$s %3$s: %5$s%6$s%n");
    }
    Logger.getLogger("").setLevel(verbose ? Level.INFO : Level.WARNING);
  }

  /**
   * Builds and starts a container named {@code name}, configured the way the default container
   * would be: from {@code config} when given (exactly as {@code -Dtrade.properties.path=config}
   * would), else from {@code -Dtrade.properties.path}, {@code TRADE_PROPERTIES_PATH}, a
   * {@code trade.properties} on the class path, or the built-in defaults (see
   * docs/configuration.md). A JVM shutdown hook closes it, so that its services leave the system
   * at once when the process is stopped, instead of after {@code FAILURETIMEOUT}.
   *
   * @param config a {@code trade.properties} file, or null
   * @throws IllegalArgumentException if {@code config} names no file or the configuration is
   *     invalid (the message names the file and the key)
   * @throws java.io.UncheckedIOException if the container cannot open its sockets
   */
  public static TRADEContainer start(String name, Path config) {
    if (config != null) {
      if (!Files.isRegularFile(config)) {
        throw new IllegalArgumentException("--config " + config + ": no such file");
      }
      // The same resolution as for the default container, so the file reads exactly as there.
      System.setProperty(PATH_PROPERTY, config.toAbsolutePath().toString());
    }
    TRADEContainer container = TRADEContainer.builder().loadConfiguration().name(name).build();
    Runtime.getRuntime().addShutdownHook(new Thread(container::close, "close-" + name));
    return container;
  }
}
