package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Settings are checked when they are given, before any socket is opened. */
class DiscoveryBuilderTest {
  @Test
  void rejectsSettingsThatCannotWork() throws IOException {
    Discovery.Builder b = Discovery.builder();
    assertEquals("10.0.0.1 is not a multicast address", assertThrows(
        IllegalArgumentException.class,
        () -> b.group(InetAddress.getByName("10.0.0.1"), 33333)).getMessage());
    assertThrows(IllegalArgumentException.class,
        () -> b.group(InetAddress.getByName("230.1.1.1"), 0));
    assertThrows(IllegalArgumentException.class, () -> b.interval(Duration.ZERO));
    assertThrows(IllegalArgumentException.class, () -> b.systemId("x".repeat(65)));
    assertThrows(IllegalArgumentException.class, () -> b.container("id", "bad\nname"));
    assertThrows(IllegalArgumentException.class, () -> b.maxClockSkew(Duration.ofSeconds(-1)));
    assertThrows(NullPointerException.class, () -> b.credentials(null));
  }

  @Test
  void startNeedsTheRequiredSettings() {
    assertEquals("Discovery needs systemId, group, container and listener", assertThrows(
        IllegalStateException.class, () -> Discovery.builder().systemId("s").start()).getMessage());
  }

  @Test
  void subnetWithAnUnknownInterfaceFailsAtStartNamingIt() throws IOException {
    Discovery.Builder b = Discovery.builder()
        .systemId("s")
        .group(InetAddress.getByName("239.255.1.1"), LoopbackMulticast.freePort())
        .container("id", "name")
        .listener((a, from, answer) -> { })
        .range(Discovery.Range.SUBNET)
        .interfaces(List.of("nosuch0"));
    IOException e = assertThrows(IOException.class, b::start);
    assertTrue(e.getMessage().startsWith("Discovery interface 'nosuch0' does not exist"));
  }
}
