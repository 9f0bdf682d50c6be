package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.address;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** Which interfaces are used and what is announced on each; uses the loopback interface only. */
class InterfacesTest {
  @BeforeEach
  void needsLoopback() {
    LoopbackMulticast.assumeUsable();
  }

  @Test
  void localhostUsesTheLoopbackInterfaceAndIgnoresNames() throws IOException {
    List<NetworkInterface> chosen = Interfaces.choose(Discovery.Range.LOCALHOST, List.of("eth9"));
    assertEquals(1, chosen.size());
    assertTrue(chosen.get(0).isLoopback());
  }

  @Test
  void aMissingSubnetInterfaceIsNamedWithTheOnesThatExist() throws IOException {
    IOException e = assertThrows(IOException.class,
        () -> Interfaces.choose(Discovery.Range.SUBNET, List.of("nosuch0")));
    String lo = LoopbackMulticast.loopback().getName();
    assertTrue(e.getMessage().startsWith("Discovery interface 'nosuch0' does not exist;"
        + " interfaces: "), e.getMessage());
    assertTrue(e.getMessage().contains(lo + " "), e.getMessage());
  }

  @Test
  void loopbackAnnouncesItsOwnAddressesOnly() throws IOException {
    NetworkInterface lo = LoopbackMulticast.loopback();
    assertEquals(List.of(address("127.0.0.1", 4000), address("127.0.0.2", 4001)),
        Interfaces.announceable(lo, List.of(address("127.0.0.1", 4000), address("10.9.8.7", 4000),
            address("127.0.0.2", 4001), address("127.0.0.1", 0), address("127.0.0.1", 4000))));
  }

  @Test
  void aWildcardStandsForTheInterfacesAddressesOfItsFamily() throws IOException {
    NetworkInterface lo = LoopbackMulticast.loopback();
    List<InetSocketAddress> v4 = new ArrayList<>();
    List<InetSocketAddress> all = new ArrayList<>();
    for (InetAddress a : Collections.list(lo.getInetAddresses())) {
      if (Announcement.isAnnounceable(a)) {
        all.add(new InetSocketAddress(a, 5000));
        if (a.getAddress().length == 4) {
          v4.add(new InetSocketAddress(a, 5000));
        }
      }
    }
    assertEquals(v4, Interfaces.announceable(lo, List.of(address("0.0.0.0", 5000))));
    assertEquals(all, Interfaces.announceable(lo, List.of(address("::", 5000))));
  }

  @Test
  void atMostSixteenAddressesAreAnnounced() throws IOException {
    List<InetSocketAddress> many = new ArrayList<>();
    for (int i = 1; i <= 20; i++) {
      many.add(address("127.0.0." + i, 4000));
    }
    assertEquals(many.subList(0, 16), Interfaces.announceable(LoopbackMulticast.loopback(), many));
  }
}
