package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import org.example.contraband.Parcel;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A Java-serialized argument whose class the providing container does not allow is refused before
 * it is deserialized, with an error naming the class and SERIALIZATIONALLOWLIST; allowed, it works.
 */
@Timeout(60)
class RemoteAllowListTest {

  public static class Inspector {
    @TRADEService
    public String describe(Object value) {
      return value instanceof Parcel ? "parcel of " + ((Parcel) value).content() : String.valueOf(value);
    }
  }

  /** Calls {@code describe(parcel)} from a second container on one that is configured by {@code allow}. */
  private static String callWithParcel(String allow) throws TRADEException {
    try (TRADEContainer provider = Hubs.hubBuilder("inspector")
            .property("SERIALIZATIONALLOWLIST", allow).build();
        TRADEContainer caller = Hubs.spokeBuilder("sender", provider).build()) {
      provider.registerAllServices(new Inspector());
      TRADEServiceConstraints describe = new TRADEServiceConstraints().name("describe");
      Await.until(Duration.ofSeconds(10), () -> !caller.getAvailableServices(describe).isEmpty(),
          "describe() to reach the caller");
      TRADEServiceInfo service = caller.getAvailableService(describe);
      assertEquals("plain", service.call(String.class, "plain")); // the link itself works
      return service.call(String.class, new Parcel("screws"));
    }
  }

  @Test
  void classOutsideTheAllowListIsRefusedByNameAndNeverDeserialized() {
    int before = Parcel.DESERIALIZED.get();
    TRADESerializationException e =
        assertThrows(TRADESerializationException.class, () -> callWithParcel(""));
    assertTrue(e.getMessage().contains("org.example.contraband.Parcel"), e.getMessage());
    assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    assertTrue(e.getMessage().contains("org.example.contraband.*"), e.getMessage());
    assertEquals(before, Parcel.DESERIALIZED.get(), "readObject ran for a refused class");
  }

  @Test
  void addingItsPackageToTheAllowListLetsItTravel() throws TRADEException {
    int before = Parcel.DESERIALIZED.get();
    assertEquals("parcel of screws", callWithParcel("org.example.contraband.*"));
    assertEquals(before + 1, Parcel.DESERIALIZED.get());
  }
}
