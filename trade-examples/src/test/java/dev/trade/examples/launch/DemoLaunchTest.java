package dev.trade.examples.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.examples.Jvms;
import dev.trade.examples.Transcript;
import java.nio.file.Path;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Runs the demo as {@code src/run-demo} does: the launcher in a JVM of its own with
 * {@code config/demo.launch}, six component JVMs finding each other by multicast on loopback. The
 * only change is a system id of its own, so that a demo running at the same time on this machine
 * stays apart. Needs only a loopback interface that is up (as in {@code unshare -n} after
 * {@code ip link set lo up}).
 */
class DemoLaunchTest {
  private static final long DEADLINE_SECONDS = 60;

  private Process launcher;

  @AfterEach
  void stopLeftovers() {
    Jvms.kill(launcher);
  }

  @Test
  void theDemoRunsItsScenarioAcrossJvmsAndExitsZero() throws Exception {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(DEADLINE_SECONDS);
    Path launchFile = Jvms.projectRoot().resolve("config/demo.launch");
    launcher = Jvms.start(Jvms.classpathOf(Launcher.class, TRADEContainer.class), Launcher.class,
        "--set", "TRADESYSID=trade-demo-test-" + UUID.randomUUID().toString().substring(0, 8),
        launchFile.toString());
    Transcript t = new Transcript(launcher.getInputStream());

    // The planner finds arm and camera by group and signature, and uses them.
    t.await("planner", "found a camera on vision, an arm on arm, a head on head and a battery on"
        + " battery", deadline);
    t.await("planner", "watching the battery: when isLow() (every 100 ms, on battery) then"
        + " batteryLow()", deadline);
    // The lookout competes for the head: told who holds it, it waits, and gets it on release.
    t.await("planner", "holding the head while looking for the cup", deadline);
    t.await("planner", "the camera sees a cup at (0.40, 0.10, 0.02)", deadline);
    t.await("lookout", "the head is busy: ", deadline);
    assertTrue(t.contains("lookout", "of container planner"), t.toString());
    t.await("planner", "container lookout waits for the head since", deadline);
    t.await("lookout", "got the head: looking around", deadline);
    t.await("lookout", "released the head", deadline);
    t.await("arm", "opening gripper at speed 40", deadline);
    t.await("planner", "picked up the cup", deadline);

    // Navigation, started late, is noticed through "joined".
    t.await("planner", "waiting for navigation to join", deadline);
    t.await("launch", "started nav (after planner printed \"waiting for navigation\")", deadline);
    t.await("planner", "joined: goTo(java.lang.String) @ nav", deadline);
    t.await("nav", "driving from the dock to the kitchen", deadline);

    // The camera is killed: "left", and a typed error from the old handle, in either order.
    t.await("planner", "watching for people", deadline);
    t.await("launch", "killing vision (SIGKILL)", deadline);
    t.await("planner", "carrying on with what is left in [MyRobot]", deadline);
    assertTrue(t.contains("planner", "left: checkFor(java.lang.String) @ vision"), t.toString());
    assertTrue(t.contains("planner", "the camera's handle failed: TRADEServiceUnavailableException:"
        + " Service not available any longer"), t.toString());
    String rest = t.await("planner", "no camera left", deadline);
    assertFalse(rest.contains("vision"), rest);
    t.await("planner", "the battery never ran low: battery watch cancelled", deadline);
    assertTrue(t.contains("planner", "% (a once notification's result)"), t.toString());
    t.await("planner", "scenario complete", deadline);

    // The launch ends with the planner and stops the others.
    t.await("launch", "planner exited with status 0", deadline);
    t.await("launch", "stopping arm, head, battery, nav", deadline);
    t.await("launch", "exit status 0", deadline);
    assertTrue(launcher.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS),
        "the launcher did not exit\n" + t);
    assertEquals(0, launcher.exitValue(), t.toString());
    assertFalse(t.contains("planner", "scenario failed"), t.toString());
    assertEquals(List.of(), launcher.descendants().toList(), "components left running");
  }
}
