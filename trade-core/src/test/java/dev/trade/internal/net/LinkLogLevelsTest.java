package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;

import dev.trade.TRADEContainer;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A link's coming and going in order is logged at DEBUG (JUL's FINE), not INFO: a container of a
 * large system makes and drops dozens of links, and each INFO line went through the logging
 * handler's lock on the control thread. A link that fails is still logged at INFO
 * ({@link SilentPeerTest}).
 */
@Timeout(60)
class LinkLogLevelsTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final LogCapture log = new LogCapture();

  @AfterEach
  void close() {
    log.close();
  }

  @Test
  void linkUpAndGoodbyeAreDebugLines() {
    try (TRADEContainer hub = Hubs.hubBuilder("hub").build()) {
      TRADEContainer spoke = Hubs.spokeBuilder("spoke", hub).build();
      try (spoke) {
        Await.until(WAIT, () -> log.has(Level.FINE, "hub: linked to spoke")
            && log.has(Level.FINE, "spoke: linked to hub"), "both ends' link lines; have " + log.lines());
      }
      Await.until(WAIT, () -> log.has(Level.FINE, "hub: link to spoke closed: said goodbye"),
          "the hub's line for the goodbye; have " + log.lines());
      assertFalse(log.has(Level.INFO, "linked to"), log.tail());
      assertFalse(log.has(Level.INFO, "link to spoke closed"), log.tail());
    }
  }
}
