package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** Every kind of bad value, and unknown keys: the whole message is asserted. */
class SettingsErrorsTest {

  @ParameterizedTest(name = "{0}={1}")
  @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
      "STARTDISCOVERY | yes | STARTDISCOVERY=yes: expected true or false",
      "USEENCRYPTION | 1 | USEENCRYPTION=1: expected true or false",
      "BROADCASTPORT | 70000 | BROADCASTPORT=70000: expected a port 1..65535",
      "BROADCASTPORT | 0 | BROADCASTPORT=0: expected a port 1..65535",
      "BROADCASTPORT | 33,333 | BROADCASTPORT=33,333: expected a port 1..65535",
      "BROADCASTINTERVAL | 0 | BROADCASTINTERVAL=0: expected a duration in milliseconds"
          + " 1..2147483647",
      "CALLTIMEOUT | 3s | CALLTIMEOUT=3s: expected a duration in milliseconds 1..2147483647",
      "CALLTIMEOUT | 2147483648 | CALLTIMEOUT=2147483648: expected a duration in milliseconds"
          + " 1..2147483647",
      "DISCOVERYTIMEOUT | -1 | DISCOVERYTIMEOUT=-1: expected a duration in milliseconds"
          + " 0..2147483647",
      "DISCOVERYCLOCKSKEW | 30s | DISCOVERYCLOCKSKEW=30s: expected a duration in milliseconds"
          + " 0..2147483647",
      "TIMEOUT_CLIENT_SOCKET | 0 | TIMEOUT_CLIENT_SOCKET=0: expected a duration in milliseconds"
          + " 1..2147483647",
      "MAXFRAMESIZE | 1023 | MAXFRAMESIZE=1023: expected a size in bytes 1024..2147483639",
      "MCAST_ADDR | 10.0.0.1 | MCAST_ADDR=10.0.0.1: expected a multicast address"
          + " 224.0.0.0..239.255.255.255 or ff00::/8",
      "MCAST_ADDR | multicast.example | MCAST_ADDR=multicast.example: expected a multicast"
          + " address 224.0.0.0..239.255.255.255 or ff00::/8",
      "MCAST_ADDR | 230.1.1 | MCAST_ADDR=230.1.1: expected a multicast address"
          + " 224.0.0.0..239.255.255.255 or ff00::/8",
      "SERVERIPS | 127.0.0.1:10002 | SERVERIPS=127.0.0.1:10002: '127.0.0.1:10002': expected"
          + " host@port, e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002",
      "CONNECTCONTAINERS | h@1, h@0 | CONNECTCONTAINERS=h@1, h@0: 'h@0': expected a port"
          + " 1..65535 (port 0, any free port, is only allowed in SERVERIPS)",
      "CONNECTCONTAINERS | h@x | CONNECTCONTAINERS=h@x: 'h@x': expected a port 0..65535 after"
          + " the last @",
      "DISCOVERYRANGE | lan | DISCOVERYRANGE=lan: expected localhost or subnet",
      "DISCOVERYINTERFACES | eth0;eth1 | DISCOVERYINTERFACES=eth0;eth1: expected network"
          + " interface names separated by commas or spaces, e.g. eth0,wlan0",
      "SERIALIZATIONALLOWLIST | com.example.*;!com.example.Bad | SERIALIZATIONALLOWLIST="
          + "com.example.*;!com.example.Bad: '!com.example.Bad': expected ';'-separated class"
          + " patterns such as com.example.Dto;com.example.model.*;com.example.**",
      "SERIALIZATIONALLOWLIST | * | SERIALIZATIONALLOWLIST=*: '*': expected ';'-separated class"
          + " patterns such as com.example.Dto;com.example.model.*;com.example.**",
      "SERIALIZATIONALLOWLIST | com.example.*;java.base/java.time.** | SERIALIZATIONALLOWLIST="
          + "com.example.*;java.base/java.time.**: 'java.base/java.time.**': a module prefix"
          + " (module/) is not supported: name the classes or packages alone, e.g. java.time.**",
      "SERIALIZATIONALLOWLIST | maxdepth=5 | SERIALIZATIONALLOWLIST=maxdepth=5: 'maxdepth=5':"
          + " expected ';'-separated class patterns such as"
          + " com.example.Dto;com.example.model.*;com.example.**",
  })
  void rejectsBadValueNamingKeyValueAndExpectation(String key, String value, String message) {
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> Settings.defaults().with(key, value));
    assertEquals(message, e.getMessage());
  }

  @Test
  void rejectsControlCharactersInText() {
    assertEquals("CONTAINERNAME=a\nb: expected a name of at most 255 bytes without control"
        + " characters", assertThrows(IllegalArgumentException.class,
            () -> Settings.defaults().with("CONTAINERNAME", "a\nb")).getMessage());
  }

  @Test
  void boundsWhatTravelsInFixedFields() {
    assertEquals("TRADESYSID=" + "s".repeat(65) + ": expected a system id of 1 to 64 bytes without"
        + " control characters", assertThrows(IllegalArgumentException.class,
            () -> Settings.defaults().with("TRADESYSID", "s".repeat(65))).getMessage());
    assertEquals("x".repeat(255), Settings.defaults().with("CONTAINERNAME", "x".repeat(255))
        .containerName());
    assertThrows(IllegalArgumentException.class,
        () -> Settings.defaults().with("CONTAINERNAME", "\u00e9".repeat(128)));
  }

  @Test
  void neverShowsCredentialsInAMessage() {
    assertEquals("CREDENTIALS=****: expected text without control characters",
        assertThrows(IllegalArgumentException.class,
            () -> Settings.defaults().with("CREDENTIALS", "se\u0000cret")).getMessage());
  }

  @ParameterizedTest
  @CsvSource(delimiter = '|', value = {
      "BROADCASTPROT | unknown key 'BROADCASTPROT' (did you mean BROADCASTPORT?)",
      "broadcastport | unknown key 'broadcastport' (did you mean BROADCASTPORT?)",
      "CALL_TIMEOUT | unknown key 'CALL_TIMEOUT' (did you mean CALLTIMEOUT?)",
      "MCASTADDR | unknown key 'MCASTADDR' (did you mean MCAST_ADDR?)",
      "SERVERIP | unknown key 'SERVERIP' (did you mean SERVERIPS?)",
  })
  void unknownKeySuggestsTheClosest(String key, String message) {
    assertEquals(message, assertThrows(IllegalArgumentException.class,
        () -> Settings.defaults().with(key, "1")).getMessage());
  }

  @Test
  void unknownKeyFarFromAllListsTheKnownKeys() {
    String message = assertThrows(IllegalArgumentException.class,
        () -> Settings.defaults().with("log.level", "FINE")).getMessage();
    assertEquals("unknown key 'log.level' (known keys: "
        + String.join(", ", Settings.defaults().asMap().keySet()) + ")", message);
  }

  @Test
  void fromPropertiesReportsTheFirstProblemInKeyOrder() {
    Properties p = new Properties();
    p.setProperty("TRADESYSID", "ok");
    p.setProperty("STARTBROADCAST", "maybe");
    p.setProperty("CALLTIMEOUT", "soon");
    assertEquals("CALLTIMEOUT=soon: expected a duration in milliseconds 1..2147483647",
        assertThrows(IllegalArgumentException.class, () -> Settings.fromProperties(p))
            .getMessage());
  }

  @Test
  void editDistance() {
    assertEquals(0, Key.distance("A", "A"));
    assertEquals(2, Key.distance("BROADCASTPROT", "BROADCASTPORT"));
    assertEquals(3, Key.distance("", "abc"));
    assertEquals(3, Key.distance("kitten", "sitting"));
  }
}
