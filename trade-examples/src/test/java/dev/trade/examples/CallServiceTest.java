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
import java.util.Set;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** CallService's arguments: typed as the parameters need, JSON for structured values. */
class CallServiceTest {
  public record Pose(double x, double y, String frame) {}

  public record Route(List<Pose> poses, Set<String> tags) {}

  public static class Robot {
    @TRADEService
    public String moveTo(Pose pose, int speed) {
      return pose + " at " + speed;
    }

    @TRADEService
    public String visit(List<Pose> poses, Map<String, Pose> named) {
      return poses.get(0).frame() + " " + named.get("home").frame();
    }

    @TRADEService
    public String follow(Route route) {
      return route.poses().get(1).frame() + " " + route.tags();
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
  void objectsInListsAndMapsNameTheirClassWhereTheSignatureCannot() throws TRADEException {
    TRADEServiceInfo visit = service("visit");
    String pose = "\"@type\": \"" + Pose.class.getName() + "\", \"x\": 1, \"y\": 2";
    Object[] args = CallService.convert(visit, List.of("[{" + pose + ", \"frame\": \"base\"}]",
        "{\"home\": {" + pose + ", \"frame\": \"dock\"}}"));
    assertEquals(List.of(new Pose(1, 2, "base")), args[0]);
    assertEquals("base dock", visit.call(String.class, args));
  }

  @Test
  void aMissingTypeIsAnErrorNamingTheArgumentAndTheFix() throws TRADEException {
    TRADEServiceInfo visit = service("visit");
    assertEquals("Argument 0 ('poses', expected java.util.List) '[{\"x\": 1}]' does not fit: at [0]:"
        + " a JSON object, but the signature does not say what it is (service infos carry raw"
        + " parameter types, such as java.util.List): name its class, {\"@type\": \"com.acme.Pose\","
        + " ...} ({\"@type\": \"java.util.Map\", ...} for a map), or pass --types with a class on the"
        + " class path that declares the method\n    for service visit(java.util.List,java.util.Map)",
        assertThrows(IllegalArgumentException.class,
            () -> CallService.convert(visit, List.of("[{\"x\": 1}]", "{}"))).getMessage());
    assertTrue(assertThrows(IllegalArgumentException.class, () -> CallService.convert(visit,
        List.of("[{\"@type\": \"com.acme.Missing\"}]", "{}"))).getMessage().contains(
        "at [0]: \"@type\" names com.acme.Missing, which is not on the class path; add it with"
        + " java -cp"));
    assertTrue(assertThrows(IllegalArgumentException.class, () -> CallService.convert(visit,
        List.of("[]", "{\"home\": {\"@type\": \"" + Route.class.getName() + "\"}}"))).getMessage()
        .contains("at .home: no \"poses\" for Route"));
    TRADEServiceInfo move = c.getAvailableService(new TRADEServiceConstraints().name("moveTo"));
    assertTrue(assertThrows(IllegalArgumentException.class, () -> CallService.convert(move,
        List.of("{\"@type\": \"" + Route.class.getName() + "\"}", "1"))).getMessage().contains(
        "\"@type\" names " + Route.class.getName() + ", which is not a " + Pose.class.getTypeName()));
  }

  @Test
  void aGenericSignatureOnTheClassPathSaysWhatListsAndMapsHold() throws TRADEException {
    TRADEServiceInfo visit = service("visit");
    Object[] args = CallService.convert(visit, List.of("[{\"x\": 1, \"y\": 2, \"frame\": \"base\"}]",
        "{\"home\": {\"x\": 0, \"y\": 0, \"frame\": \"dock\"}}"), List.of(String.class, Robot.class));
    assertEquals(List.of(new Pose(1, 2, "base")), args[0]);
    assertEquals("base dock", visit.call(String.class, args));

    // A record's components are declared with their type arguments.
    TRADEServiceInfo follow = c.getAvailableService(new TRADEServiceConstraints().name("follow"));
    args = CallService.convert(follow, List.of("{\"poses\": [{\"x\": 1, \"y\": 2, \"frame\": \"a\"},"
        + " {\"x\": 3, \"y\": 4, \"frame\": \"b\"}], \"tags\": [\"t\", \"t\"]}"));
    assertEquals("b [t]", follow.call(String.class, args));
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
