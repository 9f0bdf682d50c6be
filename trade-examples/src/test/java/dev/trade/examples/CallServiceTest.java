package dev.trade.examples;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** CallService's arguments: typed as the parameters need, JSON for structured values. */
class CallServiceTest {
  public record Pose(double x, double y, String frame) {}

  public static class Robot {
    @TRADEService
    public String moveTo(Pose pose, int speed) {
      return pose + " at " + speed;
    }

    @TRADEService
    public int sum(int[] values, List<Integer> more, Map<String, Object> options) {
      return values.length + more.size() + options.size();
    }
  }

  private final TRADEContainer c = TRADEContainer.builder().name("robot").build();

  @AfterEach
  void close() {
    c.close();
  }

  private TRADEServiceInfo service(String name) throws TRADEException {
    c.registerAllServices(new Robot());
    return c.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  @Test
  void recordsArraysListsAndMapsAreJson() throws TRADEException {
    TRADEServiceInfo move = service("moveTo");
    Object[] args = CallService.convert(move, List.of("{\"x\": 0.4, \"y\": 1, \"frame\": \"base\"}", "3"));
    assertEquals(new Pose(0.4, 1, "base"), args[0]);
    assertEquals("Pose[x=0.4, y=1.0, frame=base] at 3", move.call(String.class, args));

    TRADEServiceInfo sum = c.getAvailableService(new TRADEServiceConstraints().name("sum"));
    args = CallService.convert(sum, List.of("[1, 2, 3]", "[4, 5]", "{\"fast\": true}"));
    assertArrayEquals(new int[] {1, 2, 3}, (int[]) args[0]);
    assertEquals(List.of(4, 5), args[1]);
    assertEquals(6, sum.call(int.class, args));
  }

  @Test
  void aBadArgumentIsNumberedAsTheLibraryNumbersThem() throws TRADEException {
    TRADEServiceInfo move = service("moveTo");
    assertEquals("Argument 1 ('speed', expected " + move.serviceParameterTypeNames[1]
        + ") 'fast' does not fit: For input string: \"fast\""
        + "\n    for service moveTo(" + Pose.class.getTypeName() + ",int)",
        assertThrows(IllegalArgumentException.class,
            () -> CallService.convert(move, List.of("{\"x\":0,\"y\":0,\"frame\":\"\"}", "fast")))
            .getMessage());
    assertTrue(assertThrows(IllegalArgumentException.class,
        () -> CallService.convert(move, List.of("{\"x\":0}", "1"))).getMessage()
        .contains("no \"y\" for Pose"));
    assertTrue(assertThrows(IllegalArgumentException.class,
        () -> CallService.convert(move, List.of("{\"x\":0,", "1"))).getMessage()
        .contains("JSON: the text ends early at position 7"));
  }

  @Test
  void helpPrintsTheUsageAndExitsZero() throws IOException, InterruptedException {
    Process p = Jvms.start(Jvms.classpathOf(CallService.class, TRADEContainer.class), CallService.class,
        "--help");
    try {
      String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
      assertTrue(p.waitFor(30, TimeUnit.SECONDS), "CallService --help ended");
      assertEquals(0, p.exitValue());
      assertEquals(CallService.USAGE + System.lineSeparator(), out);
    } finally {
      Jvms.kill(p);
    }
  }
}
