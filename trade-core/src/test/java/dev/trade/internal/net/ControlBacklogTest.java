package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.net.link.ControlBacklog;
import org.junit.jupiter.api.Test;

class ControlBacklogTest {
  private final ControlBacklog backlog = new ControlBacklog();

  @Test
  void holdsUpToTheLimitAndCountsNothingForAFrameItRefuses() {
    long limit = 3 * (100 + ControlBacklog.PER_FRAME);
    long first = backlog.hold(100, limit);
    assertEquals(100 + ControlBacklog.PER_FRAME, first);
    backlog.hold(100, limit);
    backlog.hold(100, limit);
    assertEquals(limit, backlog.held(), "exactly at the limit is allowed");
    assertEquals(-1, backlog.hold(0, limit));
    assertEquals(limit, backlog.held(), "a refused frame leaves no trace");
    backlog.release(first);
    assertEquals(100 + ControlBacklog.PER_FRAME, backlog.hold(100, limit), "room again");
  }

  @Test
  void theLimitIsTwoOfTheLargestFramesAndAtLeast16MiB() {
    assertEquals(16L << 20, FrameDispatcher.backlogLimit(1024));
    assertEquals(128L << 20, FrameDispatcher.backlogLimit(64 << 20));
    assertEquals(2L * Integer.MAX_VALUE - 16, FrameDispatcher.backlogLimit(Integer.MAX_VALUE - 8));
  }
}
