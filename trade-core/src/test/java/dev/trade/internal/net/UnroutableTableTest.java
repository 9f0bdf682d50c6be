package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A table whose owner has no route yet (it came before the link states that connect its owner) is
 * not listed, and is listed as soon as its owner is routable, without being sent again; a
 * container that is cut off for a moment comes back the same way. The table of a container that
 * was reachable and is not any more is kept, but not given to newcomers.
 */
@Timeout(30)
class UnroutableTableTest {
  private final Codec tables =
      new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.DESCRIPTORS);
  private final LogCapture log = new LogCapture();
  private final String far = UUID.randomUUID().toString();
  private TRADEContainer provider;
  private RawPeer peer;
  private String me;

  @BeforeEach
  void link() throws Exception {
    provider = Hubs.hubBuilder("provider").build();
    String[] a = provider.getServerAddresses().get(0).split("@");
    peer = RawPeer.connect(new InetSocketAddress(a[0], Integer.parseInt(a[1])));
    peer.handshake("near");
    me = peer.id.toString();
    peer.send(StateFrames.links(new Topology.LinkState(me, 1, Set.of(provider.getId()))));
  }

  @AfterEach
  void close() throws Exception {
    peer.close();
    provider.close();
    log.close();
  }

  private ServiceDescriptor service(long id, String name) {
    return new ServiceDescriptor(far, "far", "host", id, name, List.of(), List.of(), "int", Set.of(),
        List.of());
  }

  private int listed(String name) {
    return provider.getAvailableServices(new TRADEServiceConstraints().name(name)).size();
  }

  /** Asks for the far table and waits for the answer: every frame sent before it was handled. */
  private Table askForFarTable() throws Exception {
    peer.send(StateFrames.tableRequest(far));
    long deadline = System.nanoTime() + Duration.ofSeconds(5).toNanos();
    while (System.nanoTime() - deadline < 0) {
      byte[] f = peer.readFrame();
      if (f[0] == Wire.TABLE) {
        ByteSource in = ByteSource.of(Arrays.copyOfRange(f, 1, f.length));
        String owner = in.readText(1024);
        long version = in.readLong();
        if (owner.equals(far)) {
          return new Table(owner, version,
              StateFrames.descriptors(tables.read(in, getClass().getClassLoader()), owner));
        }
      }
    }
    throw new AssertionError("no answer to the table request");
  }

  private void connectFar(long myVersion, long farVersion) {
    peer.send(StateFrames.links(new Topology.LinkState(me, myVersion, Set.of(provider.getId(), far))));
    peer.send(StateFrames.links(new Topology.LinkState(far, farVersion, Set.of(me))));
  }

  @Test
  void aTableBeforeItsRouteIsListedOnceTheRouteIsThere() throws Exception {
    peer.send(StateFrames.table(tables, new Table(far, 1, List.of(service(1, "farProbe")))));
    peer.send(StateFrames.delta(tables, far, 2, List.of(service(2, "farGauge")), List.of()));
    assertEquals(2, askForFarTable().version(), "the table and its delta were kept");
    assertEquals(0, listed("farProbe"), "listed without a route to its container");
    connectFar(2, 1);
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 1 && listed("farGauge") == 1,
        "the far services once routable");
    assertFalse(log.has(Level.INFO, "left or is not reachable"), log.tail());
  }

  /**
   * Links a newcomer to the provider, with or without a digest, and lists what the provider gives
   * it in the link-up exchange: "LINKS owner" and "TABLE owner" of each frame.
   */
  private List<String> linkUpExchange(boolean digests) throws Exception {
    String[] a = provider.getServerAddresses().get(0).split("@");
    try (RawPeer newcomer = RawPeer.connect(new InetSocketAddress(a[0], Integer.parseInt(a[1])))) {
      if (digests) {
        newcomer.handshakeWithDigests("newcomer");
        newcomer.send(RawPeer.frame(Wire.DIGEST, new byte[] {0})); // it has nothing
      } else {
        newcomer.handshake("newcomer");
      }
      // Answered after the exchange: the provider's own table comes a second time.
      newcomer.send(StateFrames.tableRequest(provider.getId()));
      List<String> given = new ArrayList<>();
      String own = "TABLE " + provider.getId();
      while (given.indexOf(own) == given.lastIndexOf(own)) {
        byte[] f = newcomer.readFrame();
        if (f[0] == Wire.LINKS || f[0] == Wire.TABLE) {
          String owner = ByteSource.of(Arrays.copyOfRange(f, 1, f.length)).readText(1024);
          given.add((f[0] == Wire.LINKS ? "LINKS " : "TABLE ") + owner);
        }
      }
      return given;
    }
  }

  @Test
  void theTableOfAContainerLostIsNotGivenToNewcomers() throws Exception {
    connectFar(2, 1);
    peer.send(StateFrames.table(tables, new Table(far, 1, List.of(service(1, "farProbe")))));
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 1, "the far service");
    List<String> before = linkUpExchange(true);
    assertTrue(before.contains("TABLE " + far), "given while reachable: " + before);
    peer.send(StateFrames.links(new Topology.LinkState(me, 3, Set.of(provider.getId()))));
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 0, "the far service gone");
    for (boolean digests : new boolean[] {true, false}) {
      List<String> given = linkUpExchange(digests);
      assertTrue(given.contains("LINKS " + me), "the exchange was read: " + given);
      assertFalse(given.contains("TABLE " + far), "digests " + digests + ": " + given);
      assertFalse(given.contains("LINKS " + far), "digests " + digests + ": " + given);
    }
    assertEquals(1, askForFarTable().version(), "kept, and given to one who asks for it");
  }

  @Test
  void aContainerCutOffForAMomentIsListedAgainWithoutItsTable() throws Exception {
    connectFar(2, 1);
    peer.send(StateFrames.table(tables, new Table(far, 1, List.of(service(1, "farProbe")))));
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 1, "the far service");
    peer.send(StateFrames.links(new Topology.LinkState(me, 3, Set.of(provider.getId()))));
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 0, "the far service gone");
    assertEquals(1, askForFarTable().version(), "the table is kept");
    // Back, with a newer state of its own (a container that went away is held down until then).
    connectFar(4, 2);
    Await.until(Duration.ofSeconds(5), () -> listed("farProbe") == 1, "the far service again");
  }
}
