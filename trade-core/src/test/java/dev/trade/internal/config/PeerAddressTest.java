package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

class PeerAddressTest {

  @ParameterizedTest
  @CsvSource(delimiter = '|', value = {
      "127.0.0.1@10002      | 127.0.0.1   | 10002 | 127.0.0.1@10002",
      "'  10.0.0.7@1  '     | 10.0.0.7    | 1     | 10.0.0.7@1",
      "localhost@80         | localhost   | 80    | localhost@80",
      "Robot-1.Lab.example@9 | robot-1.lab.example | 9 | robot-1.lab.example@9",
      "my_service@5000      | my_service  | 5000  | my_service@5000",
      "[::1]@10002          | ::1         | 10002 | [::1]@10002",
      "::1@10002            | ::1         | 10002 | [::1]@10002",
      "[FE80::1%eth0]@7     | fe80::1%eth0 | 7    | [fe80::1%eth0]@7",
      "::ffff:10.0.0.1@3    | ::ffff:10.0.0.1 | 3 | [::ffff:10.0.0.1]@3",
      "0.0.0.0@0            | 0.0.0.0     | 0     | 0.0.0.0@0",
      "255.255.255.255@65535 | 255.255.255.255 | 65535 | 255.255.255.255@65535",
  })
  void parsesAndPrintsBack(String text, String host, int port, String printed) {
    PeerAddress a = PeerAddress.parse(text);
    assertEquals(host, a.host());
    assertEquals(port, a.port());
    assertEquals(printed, a.toString());
    assertEquals(a, PeerAddress.parse(a.toString()));
  }

  @Test
  void portZeroMeansAnyPort() {
    assertTrue(PeerAddress.parse("127.0.0.1@0").anyPort());
  }

  @ParameterizedTest
  @CsvSource(delimiter = '|', value = {
      "127.0.0.1        | '127.0.0.1': expected host@port,"
          + " e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002",
      "@10002           | '@10002': expected an IPv4 address, host name or IPv6 address before"
          + " the last @, e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002",
      "127.0.0.1@       | '127.0.0.1@': expected a port 0..65535 after the last @",
      "127.0.0.1@65536  | '127.0.0.1@65536': expected a port 0..65535 after the last @",
      "127.0.0.1@-1     | '127.0.0.1@-1': expected a port 0..65535 after the last @",
      "127.0.0.1@+80    | '127.0.0.1@+80': expected a port 0..65535 after the last @",
      "127.0.0.1@port   | '127.0.0.1@port': expected a port 0..65535 after the last @",
      "[::1@80          | '[::1@80': expected an IPv6 address inside [ ],"
          + " e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002",
      "[127.0.0.1]@80   | '[127.0.0.1]@80': expected an IPv6 address inside [ ],"
          + " e.g. 127.0.0.1@10002, myhost@10002 or [::1]@10002",
  })
  void rejectsBadFormsWithTheirReason(String text, String message) {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> PeerAddress.parse(text));
    assertEquals(message, e.getMessage());
  }

  @ParameterizedTest
  @ValueSource(strings = {"300.1.1.1@80", "10.1@80", "01.2.3.4@80", "a b@80", "a@b@80",
      "-host@80", "host-@80", "a..b@80", "1::2::3@80", "::g@80", "fe80::1%@80", "[]@80",
      "[::1]x@80"})
  void rejectsBadHosts(String text) {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> PeerAddress.parse(text));
    assertTrue(e.getMessage().startsWith("'" + text + "': expected "), e.getMessage());
  }

  @Test
  void constructorValidatesToo() {
    assertEquals("'a b': expected an IPv4 address, host name or IPv6 address",
        assertThrows(IllegalArgumentException.class, () -> new PeerAddress("a b", 1))
            .getMessage());
    assertEquals("65536: expected a port 0..65535",
        assertThrows(IllegalArgumentException.class, () -> new PeerAddress("h", 65536))
            .getMessage());
    assertEquals("host == null",
        assertThrows(NullPointerException.class, () -> new PeerAddress(null, 1)).getMessage());
  }

  @Test
  void parsesListsWithAnySeparatorDroppingDuplicates() {
    assertEquals(
        List.of(new PeerAddress("127.0.0.1", 1), new PeerAddress("::1", 2),
            new PeerAddress("h", 3)),
        PeerAddress.parseList(" 127.0.0.1@1, [::1]@2;h@3 \t127.0.0.1@1,,"));
    assertEquals(List.of(), PeerAddress.parseList("  "));
    assertEquals(List.of(), PeerAddress.parseList(""));
  }

  @Test
  void listErrorNamesTheBadEntry() {
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> PeerAddress.parseList("127.0.0.1@1,127.0.0.1:2"));
    assertTrue(e.getMessage().startsWith("'127.0.0.1:2': expected"), e.getMessage());
  }
}
