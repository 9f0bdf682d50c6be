package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.util.Properties;
import org.junit.jupiter.api.Test;

/** The shipped config/logging.properties gives one readable line per record. */
class ShippedLoggingTest {
  @Test
  void oneLinePerRecordWithLevelLoggerAndMessage() throws IOException {
    Properties p = new Properties();
    try (InputStream in = Files.newInputStream(Path.of("..", "config", "logging.properties"))) {
      p.load(in);
    }
    String format = p.getProperty("java.util.logging.SimpleFormatter.format");
    String line = String.format(format, ZonedDateTime.of(2025, 1, 2, 3, 4, 5, 6_000_000, ZoneOffset.UTC),
        "dev.trade.internal.net.Connector lambda$attempt$1", "dev.trade.net", "INFO",
        "container arm left or is not reachable any more", "");
    assertEquals("03:04:05.006 INFO    dev.trade.net: container arm left or is not reachable any more"
        + System.lineSeparator(), line);
  }
}
