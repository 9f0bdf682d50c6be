package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Function;
import java.util.logging.LogManager;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** TRADE's logging file: named by property, then environment, then found in the working directory. */
class LoggingConfigTest {
  private static final Function<String, String> UNSET = name -> null;

  @TempDir Path dir;

  private static Function<String, String> only(String name, String value) {
    return n -> n.equals(name) ? value : null;
  }

  private Path file(String name, String level) throws IOException {
    Path f = dir.resolve(name);
    Files.writeString(f, "org.example.tradelogging." + name.replace('.', '_') + ".level = " + level
        + "\n");
    return f;
  }

  private static String level(String name) {
    return LogManager.getLogManager().getProperty(
        "org.example.tradelogging." + name.replace('.', '_') + ".level");
  }

  @Test
  void propertyThenEnvironmentThenWorkingDirectory() throws IOException {
    Path byProperty = file("p.config", "FINE");
    Path byEnv = file("e.config", "FINER");
    Path cwd = Files.createDirectories(dir.resolve("cwd"));
    Files.writeString(cwd.resolve("tradeLogging.config"),
        "org.example.tradelogging.cwd.level = FINEST\n");

    assertEquals(byProperty.toAbsolutePath().normalize(), LoggingConfig.apply(
        only(LoggingConfig.PATH_PROPERTY, byProperty.toString()),
        only(LoggingConfig.PATH_ENV, byEnv.toString()), cwd));
    assertEquals("FINE", level("p.config"));
    assertNull(level("e.config"));
    assertNull(LoggingConfig.apply(only(LoggingConfig.PATH_PROPERTY, byProperty.toString()), UNSET,
        cwd), "applied once");

    LoggingConfig.apply(UNSET, only(LoggingConfig.PATH_ENV, byEnv.toString()), cwd);
    assertEquals("FINER", level("e.config"));
    assertEquals("FINE", level("p.config"), "merged: earlier settings stay");

    LoggingConfig.apply(UNSET, UNSET, cwd);
    assertEquals("FINEST", LogManager.getLogManager().getProperty("org.example.tradelogging.cwd.level"));
    assertNull(LoggingConfig.apply(UNSET, UNSET, dir.resolve("nothing-here")));
  }

  @Test
  void aNamedFileThatIsMissingIsAnError() {
    Path missing = dir.resolve("missing.config");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
        LoggingConfig.apply(UNSET, only(LoggingConfig.PATH_ENV, missing.toString()), dir));
    assertTrue(e.getMessage().startsWith("environment variable TRADE_LOGGING_CONFIG_PATH="
        + missing + ": no such file"), e.getMessage());
  }
}
