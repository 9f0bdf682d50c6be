package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.address;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What an announcement may hold: checked when it is made, so that both ends apply one rule. */
class AnnouncementTest {
  @Test
  void wildcardAddressesAreRefusedWithAdvice() {
    assertEquals("address 0.0.0.0:4000 is a wildcard: announce the concrete addresses of"
        + " each interface", refused(List.of(address("0.0.0.0", 4000))));
    refused(List.of(address("::", 4000)));
  }

  @Test
  void addressesThatCannotBeUsedByAPeerAreRefused() {
    refused(List.of(address("239.1.2.3", 1)));
    refused(List.of(address("fe80::1", 1)));
    assertEquals("address 10.0.0.1:0 has port 0", refused(List.of(address("10.0.0.1", 0))));
    assertEquals("address nowhere.invalid:1 is not resolved",
        refused(List.of(InetSocketAddress.createUnresolved("nowhere.invalid", 1))));
    List<InetSocketAddress> seventeen = new ArrayList<>(Collections.nCopies(17,
        address("10.0.0.1", 1)));
    assertEquals("17 addresses, more than 16", refused(seventeen));
  }

  @Test
  void textsAreBoundedInUtf8BytesAndFreeOfControlCharacters() {
    assertEquals("system id is 66 bytes of UTF-8, more than 64", assertThrows(
        IllegalArgumentException.class,
        () -> new Announcement(1, "é".repeat(33), "c", "n", List.of(), 1, 1)).getMessage());
    new Announcement(1, "é".repeat(32), "c", "n".repeat(255), List.of(), 1, 1);
    assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "n".repeat(256), List.of(), 1, 1));
    assertEquals("container id contains a control character at index 1", assertThrows(
        IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c\u0000", "n", List.of(), 1, 1)).getMessage());
    assertEquals("container name is empty", assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "", List.of(), 1, 1)).getMessage());
    assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "\ud800", List.of(), 1, 1));
    assertThrows(NullPointerException.class,
        () -> new Announcement(1, null, "c", "n", List.of(), 1, 1));
  }

  @Test
  void versionSequenceAndTimestampAreChecked() {
    assertEquals("protocol version 2 is not supported (only 1)", assertThrows(
        IllegalArgumentException.class,
        () -> new Announcement(2, "s", "c", "n", List.of(), 1, 1)).getMessage());
    assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "n", List.of(), 0, 1));
    assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "n", List.of(), 1, -1));
  }

  @Test
  void addressListIsCopied() {
    List<InetSocketAddress> list = new ArrayList<>(List.of(address("10.0.0.1", 1)));
    Announcement a = new Announcement(1, "s", "c", "n", list, 1, 1);
    list.clear();
    assertEquals(1, a.addresses().size());
    assertThrows(UnsupportedOperationException.class, () -> a.addresses().clear());
  }

  private static String refused(List<InetSocketAddress> addresses) {
    return assertThrows(IllegalArgumentException.class,
        () -> new Announcement(1, "s", "c", "n", addresses, 1, 1)).getMessage();
  }
}
