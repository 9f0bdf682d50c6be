package org.example.jvm;

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
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A call or reply that would not fit in one frame ({@code MAXFRAMESIZE}) fails alone, with the
 * serialization error (an oversized exception: with its text), instead of being sent and making
 * the peer drop the link, and every other call on it, as malformed.
 */
class OversizedCallTest {
  private static final int MAX_FRAME = 64 * 1024;
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** Provided services. */
  public static final class Sizes {
    final CountDownLatch release = new CountDownLatch(1);

    @TRADEService
    public int total(byte[] a, byte[] b) {
      return a.length + b.length;
    }

    @TRADEService
    public byte[] filled(int n) {
      return new byte[n];
    }

    @TRADEService
    public void complain(int length) {
      throw new IllegalStateException("x".repeat(length));
    }

    @TRADEService
    public String held() throws InterruptedException {
      return release.await(10, TimeUnit.SECONDS) ? "released" : "not released";
    }
  }

  private final Sizes sizes = new Sizes();
  private TRADEContainer provider;
  private TRADEContainer caller;

  @BeforeEach
  void link() throws Exception {
    provider = Hubs.hubBuilder("provider").property("MAXFRAMESIZE", "" + MAX_FRAME).build();
    provider.registerAllServices(sizes, "sizes");
    caller = TRADEContainer.builder().name("caller").property("MAXFRAMESIZE", "" + MAX_FRAME)
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build();
    Await.until(WAIT, () -> caller.getAvailableServices(new TRADEServiceConstraints().inGroups("sizes"))
        .size() == 4, "the provider's services");
  }

  @AfterEach
  void close() {
    sizes.release.countDown();
    caller.close();
    provider.close();
  }

  private TRADEServiceInfo service(String name) throws Exception {
    return caller.getAvailableService(new TRADEServiceConstraints().name(name));
  }

  @Test
  void tooLargeCallsAndRepliesFailAloneAndTheLinkStays() throws Exception {
    TRADEServiceInfo total = service("total");
    TRADEServiceInfo filled = service("filled");
    TRADEServiceInfo held = service("held");
    CompletableFuture<String> bystander = CompletableFuture.supplyAsync(() -> {
      try {
        return held.call(String.class);
      } catch (Exception e) {
        return e.toString();
      }
    });

    // Each argument fits the value limit; together they do not fit a frame.
    byte[] half = new byte[MAX_FRAME / 2 + 100];
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> total.call(int.class, half, half));
    assertTrue(e.getMessage().contains("MAXFRAMESIZE"), e.getMessage());
    // One argument just under the value limit, which the call's own header pushes over the frame.
    byte[] almost = new byte[MAX_FRAME - 16];
    e = assertThrows(TRADESerializationException.class,
        () -> total.call(int.class, almost, new byte[0]));
    assertTrue(e.getMessage().contains("MAXFRAMESIZE"), e.getMessage());
    // A result that does not fit the reply frame.
    e = assertThrows(TRADESerializationException.class, () -> filled.call(byte[].class, MAX_FRAME - 16));
    assertTrue(e.getMessage().contains("MAXFRAMESIZE"), e.getMessage());
    // An exception too large for a reply: its text, shortened, still reaches the caller.
    TRADEException failure =
        assertThrows(TRADEException.class, () -> service("complain").call(void.class, 100_000));
    assertTrue(failure.getMessage().contains("IllegalStateException: xxxx"), failure.getMessage());

    assertEquals(2 * 1000, total.call(int.class, new byte[1000], new byte[1000]));
    sizes.release.countDown();
    assertEquals("released", bystander.get(10, TimeUnit.SECONDS), "the call waiting meanwhile");
  }
}
