package dev.trade.internal.admin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.text.MessageFormat;
import java.util.List;
import java.util.ResourceBundle;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

class AuditLogTest {
  /** A System.Logger that keeps what it is given. */
  static final class Recording implements System.Logger {
    final List<String> lines = new CopyOnWriteArrayList<>();

    @Override
    public String getName() {
      return AuditLog.NAME;
    }

    @Override
    public boolean isLoggable(Level level) {
      return true;
    }

    @Override
    public void log(Level level, ResourceBundle bundle, String msg, Throwable thrown) {
      lines.add(level + " " + msg);
    }

    @Override
    public void log(Level level, ResourceBundle bundle, String format, Object... params) {
      lines.add(level + " " + MessageFormat.format(format, params));
    }

    @Override
    public void log(Level level, Supplier<String> msgSupplier) {
      lines.add(level + " " + msgSupplier.get());
    }
  }

  @Test
  void atMostTheLimitPerWindowThenHowManyWereLeftOut() {
    Recording log = new Recording();
    AuditLog audit = new AuditLog(log, 3, 10_000_000_000L);
    long now = 5;
    for (int i = 0; i < 1000; i++) {
      boolean written = audit.refused("call " + i, now + i);
      assertEquals(i < 3, written, "refusal " + i);
    }
    assertEquals(List.of("WARNING refused: call 0", "WARNING refused: call 1",
        "WARNING refused: call 2"), log.lines);
    assertFalse(audit.refused("late", now + 9_999_999_999L));
    assertTrue(audit.refused("next window", now + 10_000_000_000L));
    assertEquals(List.of("WARNING 998 more refusals were not logged (at most 3 are logged per 10 s)",
        "WARNING refused: next window"), log.lines.subList(3, 5));
  }
}
