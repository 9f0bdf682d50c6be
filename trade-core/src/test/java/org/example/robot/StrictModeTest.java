package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** COPYDATAFORLOCALINVOKES: caller and provider never share a mutable object. */
class StrictModeTest {
  public record Pose(double x, double y) {}

  public static class Planner {
    List<String> received;
    final List<String> kept = new ArrayList<>(List.of("kept"));
    Object lastPose;
    String lastText;

    @TRADEService
    public List<String> plan(List<String> steps) {
      received = steps;
      steps.add("mutated by provider");
      return kept;
    }

    @TRADEService
    public Pose move(Pose pose, String text) {
      lastPose = pose;
      lastText = text;
      return pose;
    }

    @TRADEService
    public void takeThread(Thread t) {}
  }

  private static TRADEServiceInfo service(TRADEContainer c, String name) throws TRADEException {
    return c.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  @Test
  void strictModeCopiesMutableArgumentsAndResults() throws TRADEException {
    try (TRADEContainer trade = TRADEContainer.builder().copyDataForLocalInvokes(true).build()) {
      Planner p = new Planner();
      trade.registerAllServices(p);
      List<String> mine = new ArrayList<>(List.of("a"));
      @SuppressWarnings("unchecked")
      List<String> result = service(trade, "plan").call(List.class, mine);
      assertEquals(List.of("a"), mine, "the provider changed its copy, not ours");
      assertNotSame(mine, p.received);
      assertEquals(List.of("kept"), result);
      assertNotSame(p.kept, result);
      result.add("mutated by caller");
      assertEquals(List.of("kept"), p.kept);
    }
  }

  @Test
  void immutableValuesAreNotCopied() throws TRADEException {
    try (TRADEContainer trade = TRADEContainer.builder().copyDataForLocalInvokes(true).build()) {
      Planner p = new Planner();
      trade.registerAllServices(p);
      Pose pose = new Pose(1, 2);
      String text = new String("text");
      assertSame(pose, service(trade, "move").call(Pose.class, pose, text));
      assertSame(pose, p.lastPose);
      assertSame(text, p.lastText);
    }
  }

  @Test
  void withoutStrictModeObjectsAreShared() throws TRADEException {
    try (TRADEContainer trade = TRADEContainer.builder().build()) {
      Planner p = new Planner();
      trade.registerAllServices(p);
      List<String> mine = new ArrayList<>(List.of("a"));
      assertSame(p.kept, service(trade, "plan").call(List.class, mine));
      assertSame(mine, p.received);
      assertTrue(mine.contains("mutated by provider"));
    }
  }

  @Test
  void aValueThatCannotTravelFailsTypedInStrictMode() throws TRADEException {
    try (TRADEContainer trade = TRADEContainer.builder().copyDataForLocalInvokes(true).build()) {
      trade.registerAllServices(new Planner());
      TRADESerializationException e = assertThrows(TRADESerializationException.class,
          () -> service(trade, "takeThread").call(void.class, new Thread(() -> { })));
      assertTrue(e.getMessage().contains("java.lang.Thread"), e.getMessage());
    }
  }
}
