package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.net.mesh.StateFrames;
import dev.trade.internal.net.mesh.Topology;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import dev.trade.testing.Await;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An authenticated member that forges replicated state is cut off, and the container goes on: a
 * member speaks only for itself (every service of its table names it), and a container id is a
 * UUID's canonical text wherever it travels. Before, a table listing another container's service
 * was listed (and calling it by name ran the real provider's service), and a link state naming an
 * id that is not a UUID stopped routing on the provider and, flooded on, on its neighbours.
 */
@Timeout(60)
class ForgedStateTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  private final Codec tables =
      new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.DESCRIPTORS);
  private final LogCapture log = new LogCapture();
  private TRADEContainer provider;
  private TRADEContainer consumer;
  private RawPeer member;

  /** The provider offers arm(); the consumer is linked to it; a raw member links to it too. */
  @BeforeEach
  void link() throws Exception {
    provider = TRADEContainer.builder().name("provider").property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0").build();
    provider.registerAllServices(new Who());
    consumer = TRADEContainer.builder().name("consumer")
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build();
    Await.until(WAIT, () -> listed(consumer, "whoAmI") == 1, "the provider's service on the consumer");
    String[] a = provider.getServerAddresses().get(0).split("@");
    member = RawPeer.connect(new InetSocketAddress(a[0], Integer.parseInt(a[1])));
    member.handshake("member");
    member.send(StateFrames.links(
        new Topology.LinkState(member.id.toString(), 1, Set.of(provider.getId()))));
  }

  @AfterEach
  void close() throws Exception {
    member.close();
    consumer.close();
    provider.close();
    log.close();
  }

  private static int listed(TRADEContainer c, String name) {
    return c.getAvailableServices(new TRADEServiceConstraints().name(name)).size();
  }

  private static ServiceDescriptor service(String container, long id, String name) {
    return new ServiceDescriptor(container, "c", "host", id, name, List.of(), List.of(), "int",
        Set.of(), List.of());
  }

  @Test
  void aLinkStateNamingAnIdThatIsNotAUuidClosesThatLinkAndTheContainerGoesOn() throws Exception {
    member.send(StateFrames.links(new Topology.LinkState(member.id.toString(), 2,
        Set.of(provider.getId(), "not-a-uuid"))));
    member.awaitClosed(WAIT);
    Await.until(WAIT, () -> log.has(Level.INFO, "malformed replication frame",
        "'not-a-uuid' is not a container id"), "the reason");
    // Routing and replication go on: a container that comes afterwards is seen everywhere.
    try (TRADEContainer late = TRADEContainer.builder().name("late")
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build()) {
      late.registerAllServices(new Later());
      Await.until(WAIT, () -> listed(consumer, "later") == 1, "the late service on the consumer");
    }
    assertTrue(!log.has(Level.SEVERE, "control task failed"), log.tail());
  }

  @Test
  void anIdThatIsAUuidInAnotherSpellingIsRefusedToo() throws Exception {
    member.send(StateFrames.links(new Topology.LinkState(member.id.toString(), 2,
        Set.of(provider.getId(), UUID.randomUUID().toString().toUpperCase()))));
    member.awaitClosed(WAIT);
  }

  @Test
  void aTableListingAServiceOfAnotherContainerIsRefusedAndNothingOfItListed() throws Exception {
    String id = member.id.toString();
    member.send(StateFrames.table(tables, new Table(id, 1, List.of(
        service(id, 1, "ownService"),
        service(provider.getId(), 1, "impostor"), // the provider's service number 1
        service(UUID.randomUUID().toString(), 1, "nowhere")))));
    member.awaitClosed(WAIT);
    Await.until(WAIT, () -> log.has(Level.INFO, "malformed replication frame", "the table of " + id
        + " lists a service of " + provider.getId()), "the reason");
    assertEquals(0, listed(provider, "impostor"));
    assertEquals(0, listed(provider, "ownService"));
    assertEquals(0, listed(consumer, "impostor"));
    assertEquals("provider", consumer.getAvailableService(
        new TRADEServiceConstraints().name("whoAmI")).call(String.class));
  }

  /** The provider's service. */
  public static final class Who {
    @dev.trade.TRADEService
    public String whoAmI() {
      return "provider";
    }
  }

  /** A service of the late container. */
  public static final class Later {
    @dev.trade.TRADEService
    public int later() {
      return 1;
    }
  }
}
