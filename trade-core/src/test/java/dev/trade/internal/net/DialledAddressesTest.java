package dev.trade.internal.net;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.config.Settings;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.time.Scheduler;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.Properties;
import java.util.UUID;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A container remembers which peer each address it dialled belongs to only while that peer is
 * linked: containers that come and go, each on an address of its own, leave nothing behind.
 */
@Timeout(60)
class DialledAddressesTest {
  /** The containers' clock and timer (a container owns one; these networks share it). */
  private static final Scheduler SCHEDULER = Scheduler.system("test");

  @AfterAll
  static void stopTimer() {
    SCHEDULER.close();
  }

  private static final Duration WAIT = Duration.ofSeconds(10);

  @Test
  void anAddressIsForgottenWhenItsPeerIsGone() throws Exception {
    try (Network a = network("a")) {
      a.start();
      for (int i = 0; i < 3; i++) {
        try (Network b = network("b" + i)) {
          b.start();
          a.connect(b.listenAddresses().get(0));
          Await.until(WAIT, () -> a.neighbours().size() == 1, "a linked to b" + i);
          Await.until(WAIT, () -> a.dialledAddresses() == 1, "b" + i + "'s address remembered");
        }
        Await.until(WAIT, () -> a.neighbours().isEmpty(), "b" + i + " gone");
        Await.until(WAIT, () -> a.dialledAddresses() == 0, "b" + i + "'s address forgotten");
      }
    }
  }

  private static Network network(String name) {
    Properties p = new Properties();
    p.setProperty("STARTACCEPTINGCONNECTIONS", "true");
    p.setProperty("SERVERIPS", "127.0.0.1@0");
    UUID id = UUID.randomUUID();
    Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
    return new Network(Settings.fromProperties(p), id, name, "host",
        new Registry(id.toString(), name, "host"), codec, codec, null, SCHEDULER);
  }
}
