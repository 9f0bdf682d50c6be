package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.Digest;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.internal.registry.Table;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * When both sides of a new link exchange digests, each sends the other only the link states and
 * tables it lacks; a peer that does not is sent everything at once, as before.
 */
@Timeout(30)
class DigestTest {
  private final LogCapture log = new LogCapture();
  private TRADEContainer provider;
  private InetSocketAddress address;

  public static class Arm {
    @TRADEService
    public boolean openGripper(int speed) {
      return speed > 0;
    }
  }

  @BeforeEach
  void start() throws Exception {
    provider = Hubs.hubBuilder("provider").build();
    provider.registerAllServices(new Arm());
    String[] a = provider.getServerAddresses().get(0).split("@");
    address = new InetSocketAddress(a[0], Integer.parseInt(a[1]));
  }

  @AfterEach
  void close() {
    provider.close();
    log.close();
  }

  /**
   * Frame types (first byte of each), PINGs left out: read until {@code expected} have come (for
   * at most 10 s: a busy machine may be slow to send them), then for a second more, in which any
   * frame beyond them would come (a quiet second proves nothing was sent late, but a slow machine
   * cannot make it fail).
   */
  private static List<Integer> frames(RawPeer p, int expected) throws Exception {
    List<Integer> types = new ArrayList<>();
    long deadline = System.nanoTime() + Duration.ofSeconds(10).toNanos();
    while (types.size() < expected && System.nanoTime() - deadline < 0) {
      byte[] f = p.readFrame(); // the provider pings every second
      if (f[0] != Wire.PING) {
        types.add((int) f[0]);
      }
    }
    long quiet = System.nanoTime() + Duration.ofSeconds(1).toNanos();
    while (System.nanoTime() - quiet < 0) {
      byte[] f = p.readFrame();
      if (f[0] != Wire.PING) {
        types.add((int) f[0]);
      }
    }
    return types;
  }

  /** Reads up to the provider's DIGEST and returns the versions it lists. */
  private static Map<String, long[]> digestOf(RawPeer p) throws Exception {
    long deadline = System.nanoTime() + Duration.ofSeconds(5).toNanos();
    byte[] f;
    do {
      f = p.readFrame();
      assertTrue(f[0] == Wire.PING || f[0] == Wire.DIGEST, "before the digest: type " + f[0]);
    } while (f[0] != Wire.DIGEST && System.nanoTime() - deadline < 0);
    assertEquals(Wire.DIGEST, f[0]);
    return Digest.read(Arrays.copyOfRange(f, 1, f.length));
  }

  @Test
  void aNeighbourThatHasEverythingIsSentNoStateAgain() throws Exception {
    try (RawPeer p = RawPeer.connect(address)) {
      assertTrue(p.handshakeWithDigests("knowing").digests());
      String id = provider.getId();
      long[] versions = digestOf(p).get(id);
      assertNotNull(versions, "the provider lists itself");
      assertTrue(versions[0] > 0 && versions[1] > 0, "a link and a service: " + Arrays.toString(versions));
      // We claim to have the provider's link state and table at the versions it has.
      p.send(Digest.frame(List.of(new Topology.LinkState(id, versions[0], Set.of(p.id.toString()))),
          new Table(p.id.toString(), 0, List.of()),
          List.of(new Table(id, versions[1], List.of()))));
      assertEquals(List.of(), frames(p, 0));
    }
  }

  @Test
  void aNeighbourIsSentWhatItLacks() throws Exception {
    try (RawPeer p = RawPeer.connect(address)) {
      p.handshakeWithDigests("newcomer");
      digestOf(p);
      p.send(Digest.frame(List.of(), new Table(p.id.toString(), 0, List.of()), List.of()));
      List<Integer> types = frames(p, 2);
      assertEquals(List.of((int) Wire.LINKS, (int) Wire.TABLE), types, "its link state, then its table");
    }
  }

  /** The provider closes the link for {@code reason}, not later as silent (we send no pings). */
  private void awaitClosedFor(RawPeer p, String reason) throws Exception {
    p.awaitClosed(Duration.ofSeconds(5));
    Await.until(Duration.ofSeconds(5), () -> log.has(Level.INFO, "closed: malformed", reason),
        "the reason in:\n" + log.tail());
  }

  @Test
  void aSecondDigestClosesTheLink() throws Exception {
    try (RawPeer p = RawPeer.connect(address)) {
      p.handshakeWithDigests("repeating");
      digestOf(p);
      byte[] digest = Digest.frame(List.of(), new Table(p.id.toString(), 0, List.of()),
          List.of());
      p.send(digest);
      p.send(digest);
      awaitClosedFor(p, "a second DIGEST");
    }
  }

  @Test
  void aDigestOnALinkWithoutDigestsClosesIt() throws Exception {
    try (RawPeer p = RawPeer.connect(address)) {
      assertFalse(p.handshake("older").digests());
      p.send(Digest.frame(List.of(), new Table(p.id.toString(), 0, List.of()), List.of()));
      awaitClosedFor(p, "one on a link without digests");
    }
  }

  @Test
  void aPeerWithoutDigestsIsSentEverythingAtOnce() throws Exception {
    try (RawPeer p = RawPeer.connect(address)) {
      assertFalse(p.handshake("older").digests());
      List<Integer> types = frames(p, 2);
      assertEquals(List.of((int) Wire.LINKS, (int) Wire.TABLE), types);
    }
  }
}
