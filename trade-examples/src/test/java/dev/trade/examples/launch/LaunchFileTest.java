package dev.trade.examples.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.examples.Jvms;
import java.io.File;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

class LaunchFileTest {
  private static final Path FILE = Path.of("/robots/test.launch");

  private static LaunchFile parse(String... lines) {
    return LaunchFile.parse(FILE, List.of(lines));
  }

  private static String error(String... lines) {
    return assertThrows(IllegalArgumentException.class, () -> parse(lines)).getMessage();
  }

  @Test
  void readsEveryDirectiveAndOption() {
    LaunchFile f = parse(
        "# a comment",
        "deadline 45s",
        "properties ../config/robot.properties   # relative to the launch file",
        "java-options -Xmx64m -XX:+UseSerialGC",
        "",
        "component arm -- com.example.Main --component arm",
        "component planner exit after=arm delay=500ms -- com.example.Main \"two words\"",
        "component cam kill-after=planner:\"watching for people\" -- com.example.Main",
        "component nav kill-after=3s -- com.example.Main");
    assertEquals(Duration.ofSeconds(45), f.deadline());
    assertEquals(Path.of("/config/robot.properties"), f.properties());
    assertEquals(List.of("-Xmx64m", "-XX:+UseSerialGC"), f.javaOptions());
    assertEquals(List.of(
        new LaunchFile.Component("arm", null, Duration.ZERO, null, null, false, "com.example.Main",
            List.of("--component", "arm")),
        new LaunchFile.Component("planner", new LaunchFile.Event("arm", null),
            Duration.ofMillis(500), null, null, true, "com.example.Main", List.of("two words")),
        new LaunchFile.Component("cam", null, Duration.ZERO,
            new LaunchFile.Event("planner", "watching for people"), null, false, "com.example.Main",
            List.of()),
        new LaunchFile.Component("nav", null, Duration.ZERO, null, Duration.ofSeconds(3), false,
            "com.example.Main", List.of())),
        f.components());
  }

  @Test
  void classpathEntriesAreRelativeToTheFileAndFollowTheLaunchersOwn() {
    LaunchFile f = parse(
        "classpath build/classes ../lib/*",
        "classpath /opt/robot/robot.jar",
        "component a -- A");
    assertEquals(List.of("/robots/build/classes", "/lib/*", "/opt/robot/robot.jar"), f.classPath());
    assertEquals(String.join(File.pathSeparator, "trade.jar", "mine.jar", "/robots/build/classes",
        "/lib/*", "/opt/robot/robot.jar"),
        Launcher.classPath("trade.jar", List.of("mine.jar"), f));
    assertEquals(FILE + ":1: expected classpath ENTRY...", error("classpath", "component a -- A"));
  }

  @Test
  void defaultsAreNoDeadlineNoPropertiesNoOptions() {
    LaunchFile f = parse("component a -- A");
    assertNull(f.deadline());
    assertNull(f.properties());
    assertEquals(List.of(), f.javaOptions());
    assertEquals(List.of(), f.classPath());
  }

  @Test
  void eventsMatchLinesOfTheirComponentContainingTheText() {
    LaunchFile.Event e = new LaunchFile.Event("planner", "waiting for");
    assertTrue(e.matches("planner", "now waiting for navigation"));
    assertEquals(false, e.matches("arm", "now waiting for navigation"));
    assertEquals(false, new LaunchFile.Event("planner", null).matches("planner", "anything"));
    assertEquals("planner printed \"waiting for\"", e.toString());
  }

  @Test
  void mistakesNameTheFileLineAndWhatIsExpected() {
    assertEquals("/robots/test.launch:2: unknown directive 'start'; expected deadline, properties,"
        + " java-options, classpath or component", error("component a -- A", "start b"));
    assertEquals("/robots/test.launch:1: expected: component NAME [OPTION...] -- MAIN-CLASS"
        + " [ARGUMENT...]", error("component a A"));
    assertEquals("/robots/test.launch:1: 'soon' is not a duration such as 500ms or 3s",
        error("deadline soon"));
    assertEquals("/robots/test.launch:1: unknown option 'restart'; expected after=, delay=,"
        + " kill-after= or exit", error("component a restart -- A"));
    assertEquals("/robots/test.launch:2: component 'a' is listed twice",
        error("component a -- A", "component a -- B"));
    assertEquals("/robots/test.launch:1: a double quote is not closed",
        error("component a after=b:\"ready -- A"));
    assertEquals("/robots/test.launch:1: no component named 'ghost'",
        error("component a after=ghost -- A"));
    assertEquals("/robots/test.launch:1: '1arm' is not a component name (a letter, then letters,"
        + " digits, '_', '.' or '-')", error("component 1arm -- A"));
    assertEquals("/robots/test.launch: no component", error("deadline 3s"));
  }

  @Test
  void componentsThatWaitForEachOtherAreRejected() {
    assertEquals("/robots/test.launch:1: 'a' can never start: its after= events form a cycle",
        error("component a after=b -- A", "component b after=a:\"up\" -- B"));
    assertEquals("/robots/test.launch:1: 'a' cannot start after itself",
        error("component a after=a:\"up\" -- A"));
  }

  @Test
  void wordsSplitOnBlanksGroupQuotesAndStopAtComments() {
    assertEquals(List.of("a", "b c", "after=x:y z"),
        LaunchFile.words("  a \"b c\"\tafter=x:\"y z\"  # comment \"unclosed"));
    assertEquals(List.of("x#y"), LaunchFile.words("x#y"));
    assertEquals(List.of(), LaunchFile.words("# only a comment"));
  }

  @Test
  void theShippedDemoLaunchFileIsValid() throws Exception {
    LaunchFile demo = LaunchFile.read(Jvms.projectRoot().resolve("config/demo.launch"));
    assertTrue(demo.properties().endsWith(Path.of("config", "demo.properties")), demo.properties().toString());
    assertEquals(List.of("arm", "head", "battery", "vision", "planner", "lookout", "nav"),
        demo.components().stream().map(LaunchFile.Component::name).toList());
  }
}
