package dev.trade.examples.system;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.examples.Jvms;
import dev.trade.examples.Transcript;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The paper's bootstrap policy, run as a user runs it (its own JVM), against a vision component
 * in this one that only listens for announcements: what docs/middleware-services.md claims of it
 * holds. The planner announces itself only once the policy switches announcing on (the vision
 * component, which dials nobody, links to it and its service joins), and announcing is off again
 * before the planner uses the service; without an administrator's credentials nothing is
 * switched and the program fails with the typed refusal.
 */
@Timeout(180)
class BootstrapPolicyTest {
  private static final long WAIT_NANOS = TimeUnit.SECONDS.toNanos(90);
  private static final String ADMIN = "planner-admin:bootstrap-secret-1";

  @TempDir Path dir;
  private Path principals;
  private String port;
  private TRADEContainer vision;
  private Process planner;

  /** The vision service; each call also asks the planner whether it still announces itself. */
  public static final class Vision {
    final List<Object> broadcastingWhenCalled = new ArrayList<>();
    TRADEContainer container;

    @TRADEService
    public Object checkFor(String object) throws TRADEException {
      // The planner's call may come before its table does: wait for it, with a deadline.
      TRADEServiceInfo describe = null;
      long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.SECONDS.toNanos(30);
      while (describe == null && System.nanoTime() - deadline < 0) {
        for (TRADEServiceInfo s : container.getAvailableServices(new TRADEServiceConstraints()
            .inGroups("trade.system").name("describeContainer"))) {
          if (s.getContainerName().equals("planner")) {
            describe = s;
          }
        }
        java.util.concurrent.locks.LockSupport.parkNanos(1_000_000);
      }
      if (describe == null) {
        throw new IllegalStateException("checkFor was called, but the planner is not known here");
      }
      Map<?, ?> planner = container.callAs(ADMIN, describe, Map.class);
      synchronized (this) {
        broadcastingWhenCalled.add(planner.get("name") + " broadcasting=" + planner.get("broadcasting"));
      }
      return object + " at (0.4, 1.0)";
    }
  }

  @BeforeEach
  void files() throws IOException {
    principals = dir.resolve("principals");
    Files.writeString(principals, "principal planner-admin admin bootstrap-secret-1\n");
    // A port of this test's own, so that no other test's containers hear the announcements.
    port = String.valueOf(ThreadLocalRandom.current().nextInt(40000, 50000));
  }

  @AfterEach
  void stop() {
    Jvms.kill(planner);
    if (vision != null) {
      vision.close();
    }
  }

  private Process startPlanner(String credentials) throws IOException {
    List<String> command = new ArrayList<>(List.of(
        Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
        Jvms.classpathOf(BootstrapPolicy.class, TRADEContainer.class),
        BootstrapPolicy.class.getName(), "CREDENTIALS=bootstrap-test", "BROADCASTPORT=" + port,
        "PRINCIPALSFILE=" + principals));
    ProcessBuilder b = new ProcessBuilder(command).redirectErrorStream(true);
    b.environment().remove("TRADE_ADMIN_CREDENTIALS");
    if (credentials != null) {
      b.environment().put("TRADE_ADMIN_CREDENTIALS", credentials);
    }
    Process p = b.start();
    p.getOutputStream().close();
    return p;
  }

  @Test
  void thePlannerAnnouncesUntilAVisionServiceJoinsThenFallsQuietAndUsesIt() throws Exception {
    Vision service = new Vision();
    vision = TRADEContainer.builder().name("vision").property("CREDENTIALS", "bootstrap-test")
        .property("BROADCASTPORT", port).property("STARTDISCOVERY", "true")
        .property("PRINCIPALSFILE", principals.toString()).build();
    service.container = vision;
    vision.registerAllServices(service, "vision");
    assertEquals(List.of(), vision.getNeighbours(), "the vision component dials nobody");

    planner = startPlanner(ADMIN);
    Transcript out = new Transcript(planner.getInputStream());
    long deadline = System.nanoTime() + WAIT_NANOS;
    out.await(null, "BROADCASTING", deadline);
    out.await(null, "JOINED vision", deadline);
    out.await(null, "QUIET", deadline);
    out.await(null, "cup at (0.4, 1.0)", deadline);
    assertTrue(planner.waitFor(90, TimeUnit.SECONDS), "the planner exits; its output:\n" + out);
    assertEquals(0, planner.exitValue(), "its output:\n" + out);
    synchronized (service) {
      assertEquals(List.of("planner broadcasting=false"), service.broadcastingWhenCalled,
          "announcing is off before the planner uses the service it waited for");
    }
  }

  @Test
  void withoutAnAdministratorsCredentialsNothingIsSwitched() throws Exception {
    planner = startPlanner(null);
    Transcript out = new Transcript(planner.getInputStream());
    long deadline = System.nanoTime() + WAIT_NANOS;
    out.await(null, "refused: setBroadcast(boolean) of container planner", deadline); // audited
    out.await(null, "TRADENotAuthorizedException: Not authorized: setBroadcast(boolean) of"
        + " container planner needs role admin", deadline);
    assertTrue(planner.waitFor(90, TimeUnit.SECONDS), "the planner exits; its output:\n" + out);
    assertEquals(1, planner.exitValue(), "its output:\n" + out);
    assertFalse(out.contains(null, "BROADCASTING"), "its output:\n" + out);
  }
}
