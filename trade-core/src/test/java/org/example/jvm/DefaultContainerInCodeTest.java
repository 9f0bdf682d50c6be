package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The static facade takes a container configured in code, before its first use only. */
class DefaultContainerInCodeTest {
  private static final Duration WAIT = Duration.ofSeconds(30);

  @Test
  void aBuilderGivenBeforeFirstUseMakesTheDefaultContainerAndALaterOneIsRefused() throws Exception {
    try (JvmProcess p = JvmProcess.start(ConfiguredDefaultMain.class, List.of())) {
      assertEquals("name configured-in-code", p.awaitLine("name ", WAIT));
      assertEquals("refused the default container exists already (container configured-in-code,"
          + " made by an earlier TRADE call or setDefaultContainer); call"
          + " TRADE.setDefaultContainer once, before any other TRADE method",
          p.awaitLine("", WAIT));
    }
  }
}
