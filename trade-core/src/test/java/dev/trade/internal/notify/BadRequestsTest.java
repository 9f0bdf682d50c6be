package dev.trade.internal.notify;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** Every bad request is refused when made, with a message saying what to fix; nothing is scheduled. */
class BadRequestsTest {
  private final Fixture f = new Fixture();
  private final Fixture.Battery battery = new Fixture.Battery();
  private final Fixture.Sink sink = new Fixture.Sink();

  @AfterEach
  void nothingLeftScheduled() {
    assertEquals(0, f.clock.pending(), "timer tasks");
    assertEquals(List.of(), f.engine.list(), "live notifications");
  }

  private String refused(Executable request) {
    return assertThrows(TRADEBadArgumentsException.class, request).getMessage();
  }

  @Test
  void unknownTypeListsTheSupportedOnes() throws TRADEException {
    ServiceDescriptor tick = f.service(sink, "tick");
    assertEquals("Unknown notification type 'sometimes'; supported: joined, left, once, after, at,"
        + " every, if, when", refused(() -> f.request("sometimes", 10L, null, tick)));
  }

  @Test
  void argumentsOfTheWrongKind() throws TRADEException {
    ServiceDescriptor tick = f.service(sink, "tick");
    assertEquals("'every' needs a period: long milliseconds or a Duration; got java.lang.String 10s",
        refused(() -> f.request("every", "10s", null, tick)));
    assertEquals("'at' needs an Instant, or long milliseconds since the epoch; got java.time.Duration"
        + " PT1S", refused(() -> f.request("at", Duration.ofSeconds(1), null, tick)));
    assertEquals("'after' needs a delay: long milliseconds or a Duration; got java.time.Instant "
        + Instant.EPOCH, refused(() -> f.request("after", Instant.EPOCH, null, tick)));
    assertEquals("'after' needs a delay of zero or more; got -5",
        refused(() -> f.request("after", -5L, null, tick)));
    assertEquals("'joined' needs constraints (a map as docs/protocol.md describes, or a"
        + " TRADEServiceConstraints) or null as its argument; got java.lang.Long",
        refused(() -> f.request("joined", 5L, null, f.service(sink, "text"))));
  }

  @Test
  void periodsMustBePositiveAndAtLeastTheMinimum() throws TRADEException {
    ServiceDescriptor tick = f.service(sink, "tick");
    assertEquals("'every' needs a period of at least 1 ms; got 0 ms",
        refused(() -> f.request("every", 0L, null, tick)));
    assertEquals("'every' needs a period of at least 1 ms; got PT0.0005S",
        refused(() -> f.request("every", Duration.ofNanos(500_000), null, tick)));
    assertEquals("'when' needs a period of at least 1 ms; got -3 ms",
        refused(() -> f.request("when", -3L, f.service(battery, "isLowBattery"), tick)));
  }

  @Test
  void typesThatNeedAServiceSaySo() throws TRADEException {
    ServiceDescriptor tick = f.service(sink, "tick");
    assertEquals("'when' needs services[0]: the condition, a service returning boolean",
        refused(() -> f.request("when", 10L, null, tick)));
    assertEquals("'once' needs services[0]: the service to call",
        refused(() -> f.request("once", null, null, tick)));
    assertEquals("'when' needs a condition returning boolean; notACondition() returns java.lang.String",
        refused(() -> f.request("when", 10L, f.service(battery, "notACondition"), tick)));
    assertEquals("'once': add(int,int) takes 2 arguments; the request gives 1",
        refused(() -> f.request("once", new Object[] {1}, f.service(battery, "add"),
            f.service(sink, "value"))));
  }

  @Test
  void callbacksThatCannotTakeWhatTheTypeDeliversAreNamed() throws TRADEException {
    assertEquals("Callback value(java.lang.Integer) of container one cannot take what 'every'"
        + " delivers: it must take ()", refused(() -> f.request("every", 10L, null,
            f.service(sink, "value"))));
    assertEquals("Callback text(java.lang.String) of container one cannot take what 'once' delivers:"
        + " it must take (), (int) or (int, Throwable) for the result of level()",
        refused(() -> f.request("once", null, f.service(battery, "level"), f.service(sink, "text"))));
    assertEquals("Callback tick() of container one cannot take what 'joined' delivers: it must take"
        + " (dev.trade.TRADEServiceInfo)", refused(() -> f.request("joined", null, null,
            f.service(sink, "tick"))));
  }
}
