package dev.trade.internal.net;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
import java.util.logging.Level;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A call or reply that would not fit MAXFRAMESIZE fails alone with a serialization error, instead of
 * going out and making the receiver close the link under every other call.
 */
@Timeout(60)
class OversizedFramesTest {
  private static final int MAX_FRAME = 65_536;

  public static class Store {
    @TRADEService
    public int total(byte[] a, byte[] b) {
      return a.length + b.length;
    }

    @TRADEService
    public byte[] blob(int size) {
      return new byte[size];
    }

    @TRADEService
    public void fail(int size) {
      throw new IllegalStateException("x".repeat(size));
    }
  }

  private final LogCapture log = new LogCapture();
  private final TRADEContainer provider = Hubs.hubBuilder("store")
      .property("MAXFRAMESIZE", String.valueOf(MAX_FRAME)).build();
  private final TRADEContainer caller = Hubs.spokeBuilder("client", provider)
      .property("MAXFRAMESIZE", String.valueOf(MAX_FRAME)).build();

  @BeforeEach
  void register() throws TRADEException {
    provider.registerAllServices(new Store());
    Await.until(Duration.ofSeconds(10), () -> caller.getAvailableServices().size() == 3,
        "the services at the caller");
  }

  @AfterEach
  void close() {
    caller.close();
    provider.close();
    log.close();
  }

  private TRADEServiceInfo service(String name) throws TRADEException {
    return caller.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  private void assertLinkSurvived() throws TRADEException {
    assertEquals(3, service("total").call(int.class, new byte[1], new byte[2]));
    assertFalse(log.has(Level.INFO, "closed"), log.tail());
  }

  @Test
  void argumentsBeyondMaxFrameSizeFailBeforeTheyAreSent() throws TRADEException {
    // Each array fits the per-value limit; together they do not fit one frame.
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> service("total").call(int.class, new byte[40_000], new byte[40_000]));
    assertTrue(e.getMessage().contains("total(byte[],byte[])"), e.getMessage());
    assertTrue(e.getMessage().contains("MAXFRAMESIZE=" + MAX_FRAME), e.getMessage());
    assertLinkSurvived();
  }

  @Test
  void aResultBeyondMaxFrameSizeFailsAloneOnTheProvidingSide() throws TRADEException {
    // The value itself is within the limit; the reply frame around it is not.
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> service("blob").call(byte[].class, MAX_FRAME - 10));
    assertTrue(e.getMessage().contains("The result of blob(int)"), e.getMessage());
    assertTrue(e.getMessage().contains("MAXFRAMESIZE=" + MAX_FRAME), e.getMessage());
    assertEquals(100, service("blob").call(byte[].class, 100).length);
    assertLinkSurvived();
  }

  @Test
  void anExceptionBeyondMaxFrameSizeStillReachesTheCallerAsAnError() throws TRADEException {
    TRADEException e = assertThrows(TRADEException.class, () -> service("fail").call(void.class, 70_000));
    assertTrue(e.getMessage().contains("IllegalStateException"), e.getMessage());
    assertLinkSurvived();
  }
}
