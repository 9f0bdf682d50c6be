package org.example.net;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/** USEENCRYPTION=true: frames are encrypted after the handshake; both sides must agree. */
class EncryptionTest {
  public static class Echo {
    @TRADEService
    public byte[] echo(byte[] data) {
      return data;
    }
  }

  /**
   * Failure detection is not under test here: a long FAILURETIMEOUT keeps a machine too busy to
   * move 1 MiB frames for a few seconds from closing the link mid-test.
   */
  private static final String FAILURE_TIMEOUT = "60000";

  private static TRADEContainer hub(boolean encrypt) {
    return Hubs.hubBuilder("hub").property("USEENCRYPTION", Boolean.toString(encrypt))
        .property("FAILURETIMEOUT", FAILURE_TIMEOUT).build();
  }

  @Test
  void encryptedContainersCallEachOther() throws TRADEException {
    try (TRADEContainer hub = hub(true);
        TRADEContainer spoke = TRADEContainer.builder().name("spoke").property("USEENCRYPTION", "true")
            .property("FAILURETIMEOUT", FAILURE_TIMEOUT)
            .property("CONNECTCONTAINERS", hub.getServerAddresses().get(0)).build()) {
      spoke.registerAllServices(new Echo());
      TRADEServiceConstraints c = new TRADEServiceConstraints().name("echo");
      Await.until(Duration.ofSeconds(10), () -> !hub.getAvailableServices(c).isEmpty(), "echo on hub");
      byte[] data = new byte[1 << 20];
      new Random(7).nextBytes(data);
      for (int i = 0; i < 20; i++) {
        assertArrayEquals(data, hub.getAvailableService(c).call(byte[].class, (Object) data));
      }
    }
  }

  @Test
  void aContainerThatDoesNotEncryptIsRefusedWithTheReason() throws Exception {
    CountDownLatch refused = new CountDownLatch(1);
    Handler h = new Handler() {
      @Override
      public void publish(LogRecord r) {
        String text = java.text.MessageFormat.format(r.getMessage(), r.getParameters() == null
            ? new Object[0] : r.getParameters());
        if (text.contains("USEENCRYPTION differs")) {
          refused.countDown();
        }
      }

      @Override
      public void flush() {}

      @Override
      public void close() {}
    };
    Logger log = Logger.getLogger("dev.trade.net");
    log.addHandler(h);
    try (TRADEContainer hub = hub(true);
        TRADEContainer plain = Hubs.spokeBuilder("plain", hub).build()) {
      plain.registerAllServices(new Echo());
      assertTrue(refused.await(10, TimeUnit.SECONDS), "refusal logged");
      assertTrue(hub.getNeighbours().isEmpty());
      assertTrue(hub.getAvailableServices().isEmpty());
    } finally {
      log.removeHandler(h);
    }
  }
}
