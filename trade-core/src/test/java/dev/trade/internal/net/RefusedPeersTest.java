package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Containers configured with the wrong CREDENTIALS or TRADESYSID never link: both sides log the
 * refusal with its reason, no service crosses, and a correctly configured container links at once.
 */
@Timeout(60)
class RefusedPeersTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private static final TRADEServiceConstraints GATE = new TRADEServiceConstraints().inGroups("gate");
  private static final TRADEServiceConstraints VISITOR = new TRADEServiceConstraints().inGroups("visitor");

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  private final LogCapture log = new LogCapture();
  private final List<TRADEContainer> containers = new ArrayList<>();
  private TRADEContainer gate;
  private String gateAddress;

  @BeforeEach
  void startTheGate() throws TRADEException {
    gate = start(Hubs.hubBuilder("gate"));
    gate.registerAllServices(new Arm(), "gate");
    gateAddress = gate.getServerAddresses().get(0);
  }

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
    log.close();
  }

  private TRADEContainer start(TRADEContainer.Builder builder) {
    TRADEContainer c = builder.build();
    containers.add(c);
    return c;
  }

  private TRADEContainer visitor(String name, String key, String value) throws TRADEException {
    TRADEContainer c = start(TRADEContainer.builder().name(name)
        .property("CONNECTCONTAINERS", gateAddress).property(key, value));
    c.registerAllServices(new Arm(), "visitor");
    return c;
  }

  /** The visitor's own line names the gate's address; the gate's line says it refused someone. */
  private void awaitRefusalLoggedOnBothSides(String visitorReason, String gateReason) {
    String gateSocket = "/" + gateAddress.replace('@', ':');
    Await.until(WAIT, () -> log.has(Level.WARNING, "handshake with " + gateSocket + " failed: "
        + visitorReason), "the visitor's warning; have " + log.lines());
    Await.until(WAIT, () -> log.has(Level.WARNING, "refused connection from", gateReason),
        "the gate's warning; have " + log.lines());
  }

  private void assertNeverLinked(TRADEContainer visitor, String name) throws TRADEException {
    // A working link would have exchanged tables by now: prove it with a container that can.
    TRADEContainer friend = visitor("ally", "COPYDATAFORLOCALINVOKES", "false");
    Await.until(WAIT, () -> !friend.getAvailableServices(GATE).isEmpty(), "the friend to link");
    Await.until(WAIT, () -> gate.getAvailableServices(VISITOR).size() == 1,
        "the friend's service at the gate");
    assertTrue(visitor.getAvailableServices(GATE).isEmpty(), "the gate's service reached " + name);
    assertTrue(gate.getAvailableServices(VISITOR).stream()
        .noneMatch(s -> s.getContainerName().equals(name)), name + "'s service reached the gate");
    assertTrue(log.has(Level.FINE, "ally: linked to gate"), log.tail());
    assertFalse(log.has(Level.FINE, "linked to " + name), log.tail());
    assertFalse(log.has(Level.FINE, name + ": linked to"), log.tail());
  }

  @Test
  void wrongCredentialsAreRefusedOnBothSidesAndNeverShown() throws TRADEException {
    TRADEContainer impostor = visitor("impostor", "CREDENTIALS", "not-the-secret");
    String reason = "authentication failed: wrong CREDENTIALS on one side";
    awaitRefusalLoggedOnBothSides(reason, reason);
    assertNeverLinked(impostor, "impostor");
    assertTrue(log.lines().stream().noneMatch(l -> l.contains("not-the-secret") || l.contains("diarcUser")),
        "a secret in the log: " + log.lines());
  }

  @Test
  void aPeersTextCannotForgeLogLines() throws Exception {
    String[] at = gateAddress.split("@");
    try (RawPeer forger = RawPeer.connect(new InetSocketAddress(at[0], Integer.parseInt(at[1])))) {
      assertThrows(Exception.class, () -> forger.handshake("x\nSEVERE: forged", "diarcUser", "n"));
    }
    Await.until(WAIT, () -> log.has(Level.WARNING, "refused connection from",
        "other system id 'x?SEVERE: forged' (ours is 'diarc')"), "the gate's warning; have " + log.lines());
    assertTrue(log.lines().stream().noneMatch(l -> l.contains("\nSEVERE: forged")), log.tail());
  }

  @Test
  void wrongSystemIdIsRefusedOnBothSides() throws TRADEException {
    TRADEContainer stranger = visitor("stranger", "TRADESYSID", "elsewhere");
    awaitRefusalLoggedOnBothSides("other system id 'diarc' (ours is 'elsewhere')",
        "other system id 'elsewhere' (ours is 'diarc')");
    assertNeverLinked(stranger, "stranger");
  }
}
