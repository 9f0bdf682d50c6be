package dev.trade.logging;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.apache.logging.log4j.Level;
import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.core.LogEvent;
import org.apache.logging.log4j.core.Logger;
import org.apache.logging.log4j.core.appender.AbstractAppender;
import org.apache.logging.log4j.core.config.Property;
import org.junit.jupiter.api.Test;

/**
 * With log4j-jpl and log4j-core on the class path (docs/logging.md), TRADE's records arrive in
 * Log4j 2, with TRADE's logger name and level.
 */
class Log4jBridgeTest {
  /** Keeps what it is given. */
  private static final class Recording extends AbstractAppender {
    final List<LogEvent> events = new ArrayList<>();

    Recording() {
      super("recording", null, null, true, Property.EMPTY_ARRAY);
    }

    @Override
    public synchronized void append(LogEvent event) {
      events.add(event.toImmutable());
    }
  }

  @Test
  void aTradeWarningArrivesInLog4j() {
    Recording appender = new Recording();
    appender.start();
    Logger registry = (Logger) LogManager.getLogger("dev.trade.registry");
    registry.addAppender(appender);
    try {
      TradeWarning.log();
    } finally {
      registry.removeAppender(appender);
    }
    synchronized (appender) {
      assertEquals(1, appender.events.size(), appender.events.toString());
      assertEquals(Level.WARN, appender.events.get(0).getLevel());
      String message = appender.events.get(0).getMessage().getFormattedMessage();
      assertTrue(message.startsWith(TradeWarning.TEXT), message);
    }
  }
}
