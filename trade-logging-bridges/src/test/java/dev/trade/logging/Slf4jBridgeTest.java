package dev.trade.logging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.slf4j.LoggerFactory;

/**
 * With slf4j-jdk-platform-logging and Logback on the class path (docs/logging.md), TRADE's
 * records arrive in Logback, with TRADE's logger name and level.
 */
class Slf4jBridgeTest {
  @Test
  void aTradeWarningArrivesInLogback() {
    ListAppender<ILoggingEvent> appender = new ListAppender<>();
    appender.start();
    Logger registry = (Logger) LoggerFactory.getLogger("dev.trade.registry");
    registry.addAppender(appender);
    try {
      TradeWarning.log();
    } finally {
      registry.detachAppender(appender);
    }
    List<ILoggingEvent> events = appender.list;
    assertEquals(1, events.size(), events.toString());
    assertEquals("WARN", events.get(0).getLevel().toString());
    assertTrue(events.get(0).getFormattedMessage().startsWith(TradeWarning.TEXT),
        events.get(0).getFormattedMessage());
  }
}
