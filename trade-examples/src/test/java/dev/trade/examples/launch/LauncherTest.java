package dev.trade.examples.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import dev.trade.examples.Jvms;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The launcher with real child JVMs running {@link ScriptMain}. Each launch file has a deadline,
 * and each test a timeout, so that a launcher bug fails the test instead of hanging it.
 */
class LauncherTest {
  private static final Duration TIMEOUT = Duration.ofSeconds(30);
  private static final String MAIN = ScriptMain.class.getName();

  /** What a launch printed, and its exit status. */
  private record Run(int status, List<String> lines) {
    int indexOf(String line) {
      int i = lines.indexOf(line);
      assertTrue(i >= 0, "no line '" + line + "' in\n" + String.join("\n", lines));
      return i;
    }
  }

  private static Run launch(String... lines) {
    return launchWithDeadline("20s", lines);
  }

  /** Runs the launch file made of {@code lines}; prefixes in its output are one blank wide. */
  private static Run launchWithDeadline(String deadline, String... lines) {
    List<String> file = new ArrayList<>(List.of("deadline " + deadline, "java-options -Xshare:auto"));
    file.addAll(Arrays.asList(lines));
    LaunchFile launch = LaunchFile.parse(Path.of("test.launch"), file);
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
    String classpath = Jvms.classpathOf(ScriptMain.class);
    int status = assertTimeoutPreemptively(TIMEOUT,
        () -> new Launcher(launch, classpath, null, out).run());
    List<String> printed = new ArrayList<>();
    for (String line : bytes.toString(StandardCharsets.UTF_8).split("\n")) {
      printed.add(line.replaceFirst("^(\\[[^\\]]+\\]) +", "$1 "));
    }
    return new Run(status, printed);
  }

  @Test
  void prefixesOutputStartsOnEventsAndEndsWithTheExitComponent() {
    Run r = launch(
        "component server -- " + MAIN + " print:hello \"print:server up\" block",
        "component client exit after=server:\"server up\" -- " + MAIN + " print:bye exit:0");
    assertEquals(0, r.status(), String.join("\n", r.lines()));
    int up = r.indexOf("[server] server up");
    int started = r.indexOf("[launch] started client (after server printed \"server up\"), pid "
        + pidIn(r, "[launch] started client"));
    int bye = r.indexOf("[client] bye");
    int exited = r.indexOf("[launch] client exited with status 0");
    int stopping = r.indexOf("[launch] stopping server");
    assertTrue(r.indexOf("[server] hello") < up && up < started && started < bye && bye < exited
        && exited < stopping, String.join("\n", r.lines()));
  }

  @Test
  void aScriptedKillIsNotAFailure() {
    Run r = launch(
        "component victim kill-after=witness:go -- " + MAIN + " pid print:up block",
        "component witness after=victim:up -- " + MAIN + " print:go exit:0");
    assertEquals(0, r.status(), String.join("\n", r.lines()));
    assertTrue(r.indexOf("[launch] killing victim (SIGKILL)") < r.indexOf("[launch] victim is gone (killed)"));
    assertFalse(ProcessHandle.of(pidIn(r, "[victim] pid ")).map(ProcessHandle::isAlive).orElse(false));
  }

  @Test
  void theExitComponentsStatusIsTheLaunchsAndOthersAreStopped() {
    Run r = launch(
        "component idle -- " + MAIN + " pid block",
        "component main exit after=idle:pid -- " + MAIN + " exit:3");
    assertEquals(3, r.status());
    r.indexOf("[launch] stopping idle");
    assertFalse(ProcessHandle.of(pidIn(r, "[idle] pid ")).map(ProcessHandle::isAlive).orElse(false));
  }

  @Test
  void aComponentFailingOfItsOwnAccordFailsTheLaunch() {
    Run r = launch(
        "component good -- " + MAIN + " exit:0",
        "component bad -- " + MAIN + " exit:4");
    assertEquals(1, r.status());
    r.indexOf("[launch] bad exited with status 4");
  }

  @Test
  void aComponentWaitingForALineThatNeverComesFailsOnceNothingRuns() {
    Run r = launch(
        "component first -- " + MAIN + " print:something exit:0",
        "component second after=first:\"never printed\" -- " + MAIN + " exit:0");
    assertEquals(1, r.status());
    r.indexOf("[launch] nothing runs any more, and these never started: second (waits until first"
        + " printed \"never printed\")");
  }

  @Test
  void theDeadlineStopsEverythingAndFails() {
    Run r = launchWithDeadline("1s", "component sleeper -- " + MAIN + " pid block");
    assertEquals(1, r.status());
    assertTrue(r.indexOf("[launch] deadline of 1.0 s passed") < r.indexOf("[launch] stopping sleeper"));
    // The launcher names the pid as it starts the component: a JVM that needs more than the
    // second to start (a busy machine) prints nothing of its own before it is stopped.
    assertFalse(ProcessHandle.of(pidIn(r, "[launch] started sleeper, pid ")).map(ProcessHandle::isAlive)
        .orElse(false));
  }

  /** The number at the end of the first line starting with {@code start}. */
  private static long pidIn(Run r, String start) {
    for (String line : r.lines()) {
      if (line.startsWith(start)) {
        return Long.parseLong(line.substring(line.lastIndexOf(' ') + 1));
      }
    }
    throw new AssertionError("no line starting with '" + start + "' in\n" + String.join("\n", r.lines()));
  }
}
