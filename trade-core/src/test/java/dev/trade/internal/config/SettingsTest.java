package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.codec.AllowList;
import java.net.InetAddress;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class SettingsTest {

  @Test
  void theDefaultCredentialsAreFlaggedOnlyWhereTheContainerReachesBeyondItsHost() {
    Settings d = Settings.defaults();
    assertFalse(d.defaultCredentialsBeyondThisHost(), "no networking");
    assertFalse(d.with("STARTDISCOVERY", "true").with("STARTACCEPTINGCONNECTIONS", "true")
        .with("SERVERIPS", "127.0.0.1@0").with("CONNECTCONTAINERS", "localhost@10002,[::1]@10003")
        .defaultCredentialsBeyondThisHost(), "loopback only");
    assertTrue(d.with("STARTDISCOVERY", "true").with("DISCOVERYRANGE", "subnet")
        .defaultCredentialsBeyondThisHost(), "subnet discovery");
    assertTrue(d.with("SERVERIPS", "0.0.0.0@10002").defaultCredentialsBeyondThisHost(), "any address");
    assertTrue(d.with("CONNECTCONTAINERS", "robot2@10002").defaultCredentialsBeyondThisHost(),
        "another host");
    assertFalse(d.with("CONNECTCONTAINERS", "robot2@10002").with("CREDENTIALS", "lab-secret")
        .defaultCredentialsBeyondThisHost(), "credentials of its own");
  }

  /** Settings that load must build a container: its allow-list takes every pattern they accept. */
  @Test
  void everyAcceptedClassPatternIsOneTheAllowListTakes() {
    Settings s = Settings.defaults().with("SERIALIZATIONALLOWLIST",
        "com.example.Dto;com.example.model.*;com.example.**;com.example.Dto*;Top;a_b.$c.D$1");
    assertEquals(6, s.serializationAllowList().size());
    AllowList list = AllowList.withDefaults();
    for (String pattern : s.serializationAllowList()) {
      list.add(pattern);
    }
    assertTrue(list.isAllowed("com.example.sub.Dto2"));
  }

  @Test
  void defaultsTurnNetworkingOffAndKeepTradeValues() throws Exception {
    Settings d = Settings.defaults();
    assertEquals("", d.containerName());
    assertFalse(d.startDiscovery());
    assertFalse(d.startBroadcast());
    assertEquals(InetAddress.getByName("230.1.1.1"), d.multicastAddress());
    assertEquals(33333, d.broadcastPort());
    assertEquals(Duration.ofMillis(3000), d.broadcastInterval());
    assertEquals(Duration.ofMillis(3000), d.discoveryTimeout());
    assertEquals(Duration.ofMillis(3000), d.callContainerDiscoveryTimeout());
    assertFalse(d.startAcceptingConnections());
    assertEquals(List.of(), d.serverAddresses());
    assertEquals(List.of(), d.connectContainers());
    assertTrue(d.scanForServer());
    assertEquals(Duration.ofMillis(3000), d.clientSocketTimeout());
    assertEquals(Duration.ofMillis(5000), d.callCheckTime());
    assertFalse(d.useEncryption());
    assertEquals("diarcUser", d.credentials());
    assertEquals("diarc", d.tradeSysId());
    assertFalse(d.copyDataForLocalInvokes());
    assertEquals(Duration.ofSeconds(30), d.callTimeout());
    assertEquals(Duration.ofMillis(1000), d.heartbeatInterval());
    assertEquals(Duration.ofMillis(3000), d.failureTimeout());
    assertEquals(DiscoveryRange.LOCALHOST, d.discoveryRange());
    assertEquals(0, d.discoveryRange().ttl());
    assertEquals(List.of(), d.discoveryInterfaces());
    assertEquals(Duration.ofSeconds(30), d.discoveryClockSkew());
    assertEquals(List.of(), d.serializationAllowList());
    assertEquals(64 * 1024 * 1024, d.maxFrameSize());
    assertEquals(Duration.ofSeconds(1), d.hookTimeout());
    assertFalse(d.hookSystemServices());
    assertEquals("", d.callLog());
    assertEquals(List.of(), d.callLogGroups());
    assertEquals(10 * 1024 * 1024, d.callLogMaxBytes());
  }

  @Test
  void asMapListsEveryKeyInCanonicalOrder() {
    Map<String, String> map = Settings.defaults().asMap();
    assertEquals(List.of("CONTAINERNAME", "STARTDISCOVERY", "STARTBROADCAST", "MCAST_ADDR",
        "BROADCASTPORT", "BROADCASTINTERVAL", "DISCOVERYTIMEOUT", "CALLCONTAINERDISCOVERYTIMEOUT",
        "STARTACCEPTINGCONNECTIONS", "SERVERIPS", "CONNECTCONTAINERS", "SCANFORSERVER",
        "TIMEOUT_CLIENT_SOCKET", "CALLCHECKTIME", "USEENCRYPTION", "CREDENTIALS", "TRADESYSID",
        "COPYDATAFORLOCALINVOKES", "KEEPTRYING", "NETWORKINTERFACE", "CALLTIMEOUT",
        "HEARTBEATINTERVAL", "FAILURETIMEOUT",
        "DISCOVERYRANGE", "DISCOVERYINTERFACES", "DISCOVERYCLOCKSKEW", "SERIALIZATIONALLOWLIST",
        "MAXFRAMESIZE", "PRINCIPALSFILE", "PRINCIPAL", "PROVIDERCLASSES", "HOOKTIMEOUT",
        "HOOKSYSTEMSERVICES", "CALLLOG", "CALLLOGGROUPS", "CALLLOGMAXBYTES"),
        List.copyOf(map.keySet()));
    assertEquals("33333", map.get("BROADCASTPORT"));
    assertEquals("", map.get("SERVERIPS"));
    assertEquals("localhost", map.get("DISCOVERYRANGE"));
    assertThrows(UnsupportedOperationException.class, () -> map.put("X", "y"));
  }

  @Test
  void parsesEveryKey() throws Exception {
    Settings s = Settings.defaults()
        .with("CONTAINERNAME", "  arm-1 ")
        .with("STARTDISCOVERY", "TRUE")
        .with("STARTBROADCAST", "True")
        .with("MCAST_ADDR", "239.255.0.9")
        .with("BROADCASTPORT", "1")
        .with("BROADCASTINTERVAL", "100")
        .with("DISCOVERYTIMEOUT", "0")
        .with("CALLCONTAINERDISCOVERYTIMEOUT", "0")
        .with("STARTACCEPTINGCONNECTIONS", "true")
        .with("SERVERIPS", "127.0.0.1@10002, 0.0.0.0@0")
        .with("CONNECTCONTAINERS", "127.0.0.1@10002;[::1]@10003")
        .with("SCANFORSERVER", "false")
        .with("TIMEOUT_CLIENT_SOCKET", "2147483647")
        .with("CALLCHECKTIME", "1")
        .with("USEENCRYPTION", "true")
        .with("CREDENTIALS", "s3cret")
        .with("TRADESYSID", "lab")
        .with("COPYDATAFORLOCALINVOKES", "true")
        .with("CALLTIMEOUT", "5000")
        .with("HEARTBEATINTERVAL", "100")
        .with("FAILURETIMEOUT", "1000")
        .with("DISCOVERYRANGE", "Subnet")
        .with("DISCOVERYINTERFACES", "eth0, wlan0 eth0")
        .with("DISCOVERYCLOCKSKEW", "0")
        .with("SERIALIZATIONALLOWLIST",
            "com.example.Dto; com.example.model.*;java.time.**;")
        .with("MAXFRAMESIZE", "1024");
    assertEquals("arm-1", s.containerName());
    assertTrue(s.startDiscovery());
    assertTrue(s.startBroadcast());
    assertEquals(InetAddress.getByName("239.255.0.9"), s.multicastAddress());
    assertEquals(1, s.broadcastPort());
    assertEquals(Duration.ofMillis(100), s.broadcastInterval());
    assertEquals(Duration.ZERO, s.discoveryTimeout());
    assertEquals(Duration.ZERO, s.callContainerDiscoveryTimeout());
    assertTrue(s.startAcceptingConnections());
    assertEquals(List.of(new PeerAddress("127.0.0.1", 10002), new PeerAddress("0.0.0.0", 0)),
        s.serverAddresses());
    assertEquals(List.of(new PeerAddress("127.0.0.1", 10002), new PeerAddress("::1", 10003)),
        s.connectContainers());
    assertFalse(s.scanForServer());
    assertEquals(Duration.ofMillis(Integer.MAX_VALUE), s.clientSocketTimeout());
    assertEquals(Duration.ofMillis(1), s.callCheckTime());
    assertTrue(s.useEncryption());
    assertEquals("s3cret", s.credentials());
    assertEquals("lab", s.tradeSysId());
    assertTrue(s.copyDataForLocalInvokes());
    assertEquals(Duration.ofSeconds(5), s.callTimeout());
    assertEquals(Duration.ofMillis(100), s.heartbeatInterval());
    assertEquals(Duration.ofSeconds(1), s.failureTimeout());
    assertEquals(DiscoveryRange.SUBNET, s.discoveryRange());
    assertEquals(1, s.discoveryRange().ttl());
    assertEquals(List.of("eth0", "wlan0"), s.discoveryInterfaces());
    assertEquals(Duration.ZERO, s.discoveryClockSkew());
    assertEquals(List.of("com.example.Dto", "com.example.model.*", "java.time.**"),
        s.serializationAllowList());
    assertEquals(1024, s.maxFrameSize());

    // Canonical text loads back into equal settings.
    Properties p = new Properties();
    p.putAll(s.asMap());
    assertEquals(s, Settings.fromProperties(p));
    assertEquals("127.0.0.1@10002,[::1]@10003", s.asMap().get("CONNECTCONTAINERS"));
    assertEquals("subnet", s.asMap().get("DISCOVERYRANGE"));
  }

  @ParameterizedTest
  @CsvSource({"MCAST_ADDR, FF02::1:5, ff02:0:0:0:0:0:1:5", "MCAST_ADDR, 224.0.0.1, 224.0.0.1",
      "BROADCASTPORT, 65535, 65535", "BROADCASTINTERVAL, 007, 7", "MAXFRAMESIZE, 2147483639,"
      + " 2147483639", "STARTDISCOVERY, FALSE, false", "DISCOVERYRANGE, LOCALHOST, localhost"})
  void normalisesValues(String key, String value, String canonical) {
    assertEquals(canonical, Settings.defaults().with(key, value).asMap().get(key));
  }

  @Test
  void emptyOrBlankValueMeansTheDefault() {
    Settings changed = Settings.defaults().with("BROADCASTPORT", "1").with("CREDENTIALS", "x");
    assertEquals(Settings.defaults(),
        changed.with("BROADCASTPORT", "").with("CREDENTIALS", " \t"));
  }

  @Test
  void withReturnsACopy() {
    Settings d = Settings.defaults();
    Settings s = d.with("CALLTIMEOUT", "1");
    assertEquals(Duration.ofMillis(30000), d.callTimeout());
    assertEquals(Duration.ofMillis(1), s.callTimeout());
    assertNotEquals(d, s);
    assertEquals(d, s.with("CALLTIMEOUT", "30000"));
    assertEquals(d.hashCode(), s.with("CALLTIMEOUT", "30000").hashCode());
  }

  @Test
  void listsAreUnmodifiable() {
    Settings s = Settings.defaults().with("SERVERIPS", "h@1").with("DISCOVERYINTERFACES", "lo");
    assertThrows(UnsupportedOperationException.class, () -> s.serverAddresses().clear());
    assertThrows(UnsupportedOperationException.class, () -> s.discoveryInterfaces().clear());
  }

  @Test
  void legacyKeyIsAcceptedAndIgnored() {
    Settings d = Settings.defaults();
    assertSame(d, d.with("RUNWEBSERVER", "whatever"));
    Properties p = new Properties();
    p.setProperty("RUNWEBSERVER", "false");
    assertEquals(d, Settings.fromProperties(p));
    assertFalse(d.asMap().containsKey("RUNWEBSERVER"));
  }

  @Test
  void fromPropertiesStartsFromDefaultsAndReadsTheDefaultsChain() {
    Properties base = new Properties();
    base.setProperty("TRADESYSID", "lab");
    Properties p = new Properties(base);
    p.setProperty("CALLTIMEOUT", " 10 ");
    Settings s = Settings.fromProperties(p);
    assertEquals("lab", s.tradeSysId());
    assertEquals(Duration.ofMillis(10), s.callTimeout());
    assertEquals(33333, s.broadcastPort());
    assertEquals(Settings.defaults(), Settings.fromProperties(new Properties()));
  }

  @Test
  void withAllLayersOnTopOfThisInstance() {
    Properties p = new Properties();
    p.setProperty("BROADCASTPORT", "4000");
    Settings s = Settings.defaults().with("TRADESYSID", "lab").withAll(p);
    assertEquals("lab", s.tradeSysId());
    assertEquals(4000, s.broadcastPort());
  }

  @Test
  void toStringMasksCredentials() {
    String text = Settings.defaults().with("CREDENTIALS", "hunter2").toString();
    assertFalse(text.contains("hunter2"), text);
    assertTrue(text.startsWith("Settings{CONTAINERNAME=, STARTDISCOVERY=false,"), text);
    assertTrue(text.contains(", CREDENTIALS=****, TRADESYSID=diarc,"), text);
    assertTrue(text.endsWith(", MAXFRAMESIZE=67108864, PRINCIPALSFILE=, PRINCIPAL=****,"
        + " PROVIDERCLASSES=, HOOKTIMEOUT=1000, HOOKSYSTEMSERVICES=false, CALLLOG=, CALLLOGGROUPS=,"
        + " CALLLOGMAXBYTES=10485760}"), text);
    assertEquals("hunter2", Settings.defaults().with("CREDENTIALS", "hunter2").credentials());
    String principal = Settings.defaults().with("PRINCIPAL", "alice:hunter3").toString();
    assertFalse(principal.contains("hunter3"), principal);
  }

  @Test
  void nullsAreRejected() {
    assertEquals("key == null", assertThrows(NullPointerException.class,
        () -> Settings.defaults().with(null, "x")).getMessage());
    assertEquals("value == null", assertThrows(NullPointerException.class,
        () -> Settings.defaults().with("CALLTIMEOUT", null)).getMessage());
    assertEquals("properties == null", assertThrows(NullPointerException.class,
        () -> Settings.fromProperties(null)).getMessage());
  }

  @Test
  void tradesNetworkInterfaceStandsInForAnEmptyDiscoveryInterfaces() {
    Settings trade = Settings.defaults().with("NETWORKINTERFACE", "eth1");
    assertEquals(List.of("eth1"), trade.discoveryInterfaces());
    assertEquals(List.of("wlan0"), trade.with("DISCOVERYINTERFACES", "wlan0").discoveryInterfaces());
    assertEquals(List.of(), Settings.defaults().discoveryInterfaces());
    assertEquals(true, Settings.defaults().keepTrying());
    assertEquals(false, Settings.defaults().with("KEEPTRYING", "false").keepTrying());
  }
}
