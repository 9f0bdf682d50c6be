package dev.trade.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.examples.launch.Launcher;
import dev.trade.examples.robot.ComponentMain;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The commands of docs/quickstart.md, with the shipped example configurations: an arm in one JVM,
 * {@link CallService} in another, by hand and from the example launch file. The configurations are copied with a system id (and port) of
 * the test's own appended, so that a quickstart running on this machine at the same time stays
 * apart; everything else is as shipped.
 */
class QuickstartCommandsTest {
  private static final long DEADLINE_SECONDS = 30;
  private static final String CLASSPATH = Jvms.classpathOf(ComponentMain.class, TRADEContainer.class);

  @TempDir
  Path dir;
  private Process arm;
  private Process call;

  @AfterEach
  void stop() {
    Jvms.kill(call);
    Jvms.kill(arm);
  }

  @Test
  void twoJvmsFindEachOtherByDiscoveryOnLoopback() throws Exception {
    long deadline = deadline();
    String system = "TRADESYSID=quickstart-test-" + UUID.randomUUID();
    Path config = copy("discovery-localhost.properties", system);
    arm = Jvms.start(CLASSPATH, ComponentMain.class, "--component", "arm", "--config", config.toString());
    Transcript armOut = new Transcript(arm.getInputStream());
    armOut.await(null, "ready: closeGripper(), moveTo(dev.trade.examples.robot.Pose), openGripper(int)"
        + " in [MyRobot] on arm", deadline);

    call = Jvms.start(CLASSPATH, CallService.class, "--config", config.toString(),
        "--groups", "MyRobot", "openGripper", "40");
    Transcript callOut = new Transcript(call.getInputStream());
    callOut.await(null, "openGripper(int) @ arm returned true", deadline);
    armOut.await(null, "opening gripper at speed 40", deadline);
    assertExitsZero(call, callOut, deadline);
  }

  @Test
  void aSpokeConnectsToItsHubStartedAfterIt() throws Exception {
    long deadline = deadline();
    String system = "TRADESYSID=quickstart-test-" + UUID.randomUUID();
    int port = freePort();
    Path hub = copy("hub.properties", system + "\nSERVERIPS=127.0.0.1@" + port);
    Path spoke = copy("spoke.properties", system + "\nCONNECTCONTAINERS=127.0.0.1@" + port);
    call = Jvms.start(CLASSPATH, CallService.class, "--config", spoke.toString(),
        "closeGripper");
    Transcript callOut = new Transcript(call.getInputStream());
    arm = Jvms.start(CLASSPATH, ComponentMain.class, "--component", "arm", "--config", hub.toString());
    Transcript armOut = new Transcript(arm.getInputStream());
    callOut.await(null, "closeGripper() @ arm returned", deadline);
    armOut.await(null, "closing gripper", deadline);
    assertExitsZero(call, callOut, deadline);
  }

  @Test
  void theLaunchFileRunsBothWithOneCommand() throws Exception {
    long deadline = deadline();
    call = Jvms.start(Jvms.classpathOf(Launcher.class, TRADEContainer.class), Launcher.class,
        "--set", "TRADESYSID=quickstart-test-" + UUID.randomUUID(),
        Jvms.projectRoot().resolve("config/examples/arm-and-call.launch").toString());
    Transcript out = new Transcript(call.getInputStream());
    out.await("launch", "started call (after arm printed \"ready\")", deadline);
    out.await("arm", "opening gripper at speed 40", deadline);
    out.await("call", "openGripper(int) @ arm returned true", deadline);
    out.await("launch", "done in", deadline);
    assertExitsZero(call, out, deadline);
  }

  private static long deadline() {
    return System.nanoTime() + TimeUnit.SECONDS.toNanos(DEADLINE_SECONDS);
  }

  /** The shipped example {@code name} with {@code lines} appended (a later key wins). */
  private Path copy(String name, String lines) throws IOException {
    Path shipped = Jvms.projectRoot().resolve("config/examples").resolve(name);
    Path copy = dir.resolve(name);
    Files.writeString(copy, Files.readString(shipped) + "\n" + lines + "\n");
    return copy;
  }

  private static int freePort() throws IOException {
    try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      return s.getLocalPort();
    }
  }

  private static void assertExitsZero(Process p, Transcript out, long deadline)
      throws InterruptedException {
    assertTrue(p.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS),
        "did not exit\n" + out);
    assertEquals(0, p.exitValue(), out.toString());
  }
}
