package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Containers with different MAXFRAMESIZE: each tells its own in the handshake, so a call, result
 * or exception larger than the receiving side accepts fails alone, with an error that names that
 * limit, instead of going out and making the receiver close the link under every other call.
 */
@Timeout(60)
class UnequalFrameLimitsTest {
  private static final int SMALL = 65_536;
  private static final int LARGE = 1 << 20;
  private static final String STORE_LIMIT = "65536, which container 'store' accepts";
  private static final String CLIENT_LIMIT = "65536, which container 'client' accepts";

  private final LogCapture log = new LogCapture();
  private final List<TRADEContainer> containers = new ArrayList<>();

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
    log.close();
  }

  private TRADEContainer container(String name, int maxFrame, TRADEContainer connectTo) {
    TRADEContainer c = Hubs.hubBuilder(name).property("CONNECTCONTAINERS",
            connectTo == null ? "" : connectTo.getServerAddresses().get(0))
        .property("MAXFRAMESIZE", String.valueOf(maxFrame)).build();
    containers.add(c);
    return c;
  }

  /** The store's services as {@code caller} sees them, once all three are there. */
  private static TRADEServiceInfo service(TRADEContainer caller, String name)
      throws TRADEException {
    TRADEServiceConstraints all = new TRADEServiceConstraints().inGroups("store");
    Await.until(Duration.ofSeconds(10), () -> caller.getAvailableServices(all).size() == 3,
        "the store's services at " + caller.getName());
    return caller.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  /** Makes {@code client} call {@code service} and expects the serialization error's texts. */
  private static void assertTooLarge(TRADEContainer client, String service, String... texts) {
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> {
          if (service.equals("total")) {
            service(client, "total").call(int.class, new byte[40_000], new byte[40_000]);
          } else {
            service(client, "blob").call(byte[].class, 100_000);
          }
        });
    for (String text : texts) {
      assertTrue(e.getMessage().contains(text), e.getMessage());
    }
  }

  private void assertNoLinkClosed(TRADEContainer caller) throws TRADEException {
    assertEquals(3, service(caller, "total").call(int.class, new byte[1], new byte[2]));
    assertFalse(log.has(Level.INFO, "closed"), log.tail());
  }

  @Test
  void argumentsLargerThanTheProviderAcceptsFailAtTheCaller() throws TRADEException {
    TRADEContainer client = linked(SMALL, LARGE);
    // Within the client's own limit, beyond the store's.
    assertTooLarge(client, "total", "total(byte[],byte[])", STORE_LIMIT);
    assertNoLinkClosed(client);
  }

  @Test
  void aResultOrExceptionLargerThanTheCallerAcceptsFailsThatCallAlone() throws TRADEException {
    TRADEContainer client = linked(LARGE, SMALL);
    assertTooLarge(client, "blob", "The result cannot travel", CLIENT_LIMIT);
    assertEquals(100, service(client, "blob").call(byte[].class, 100).length);

    TRADEException thrown = assertThrows(TRADEException.class,
        () -> service(client, "fail").call(void.class, 70_000));
    assertFalse(thrown instanceof TRADEInvocationException, thrown.toString());
    assertTrue(thrown.getMessage().contains("The reply cannot travel"), thrown.getMessage());
    // A small exception still comes back as what the service threw.
    TRADEInvocationException small = assertThrows(TRADEInvocationException.class,
        () -> service(client, "fail").call(void.class, 10));
    assertTrue(small.getCause() instanceof IllegalStateException, small.toString());
    assertNoLinkClosed(client);
  }

  /** A store and a client linked to it; the client. */
  private TRADEContainer linked(int storeLimit, int clientLimit) throws TRADEException {
    TRADEContainer store = container("store", storeLimit, null);
    store.registerAllServices(new OversizedFramesTest.Store(), "store");
    return container("client", clientLimit, store);
  }

  /**
   * A store and a client that both link only to a hub (limit LARGE), so that calls between them
   * are forwarded; the client, once it sees the store's services through the hub.
   */
  private TRADEContainer throughAHub(int storeLimit, int clientLimit) throws TRADEException {
    TRADEContainer hub = container("hub", LARGE, null);
    TRADEContainer store = container("store", storeLimit, hub);
    store.registerAllServices(new OversizedFramesTest.Store(), "store");
    TRADEContainer client = container("client", clientLimit, hub);
    assertEquals(2, service(client, "total").getDistance());
    return client;
  }

  @Test
  void aForwarderRefusesACallLargerThanItsNextHopAccepts() throws TRADEException {
    TRADEContainer client = throughAHub(SMALL, LARGE);
    assertTooLarge(client, "total", "Cannot pass the call on", STORE_LIMIT);
    assertNoLinkClosed(client);
  }

  @Test
  void aReplyLargerThanTheNextHopTowardsTheCallerAcceptsIsReplacedOnTheWay() throws TRADEException {
    TRADEContainer client = throughAHub(LARGE, SMALL);
    assertTooLarge(client, "blob", "The result cannot travel", CLIENT_LIMIT);
    assertNoLinkClosed(client);
  }
}
