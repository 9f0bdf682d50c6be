package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import java.util.List;
import java.util.UUID;
import org.junit.jupiter.api.Test;

class HandshakeTest {

  @Test
  void fieldsLongerThanAHelloHoldsAreRefusedWhenTheContainerIsBuilt() {
    // 100 characters of 3 bytes each: 300 bytes of UTF-8, more than a str8 holds.
    String name = "\u2603".repeat(100);
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> TRADEContainer.builder().name(name).property("STARTACCEPTINGCONNECTIONS", "true")
            .property("SERVERIPS", "127.0.0.1@0").build());
    // The configuration refuses it first, naming the key and the limit.
    assertTrue(e.getMessage().startsWith("CONTAINERNAME="), e.getMessage());
    assertTrue(e.getMessage().endsWith("expected a name of at most 255 bytes without control"
        + " characters"), e.getMessage());

    e = assertThrows(IllegalArgumentException.class, () -> new Handshake(new Handshake.Identity(
        "s".repeat(256), UUID.randomUUID(), "arm", "localhost", List.of()), "diarcUser"));
    assertTrue(e.getMessage().startsWith("TRADESYSID is 256 bytes long"), e.getMessage());
  }

  @Test
  void fieldsOfExactly255BytesAreFine() {
    new Handshake(new Handshake.Identity("s".repeat(255), UUID.randomUUID(), "n".repeat(255),
        "h".repeat(255), List.of()), "diarcUser");
  }
}
