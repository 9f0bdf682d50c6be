package org.example.jvm;

import dev.trade.TRADE;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.testing.Await;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;

/**
 * A component as DIARC writes one (TRADE-API.md: {@code DiarcComponent.shutdown()} deregisters from
 * a JVM shutdown hook): it registers with the static {@link TRADE} methods, and its own shutdown
 * hook deregisters once its standard input ends, then prints {@code DEREGISTERED} or what failed.
 * It starts its own exit as soon as it sees a service named {@code left} (its peer's), and has
 * printed {@code READY}.
 *
 * <p>Arguments: the settings of the default container, as {@code KEY=VALUE}.
 */
public final class ShutdownHookMain {
  private ShutdownHookMain() {}

  /** The component's one service. */
  public static final class Lamp {
    @TRADEService
    public boolean lampOn() {
      return true;
    }
  }

  public static void main(String[] args) throws Exception {
    Path settings = Files.createTempFile("trade-hook", ".properties");
    settings.toFile().deleteOnExit();
    Files.writeString(settings, String.join("\n", args) + "\n");
    System.setProperty("trade.properties.path", settings.toString());
    Lamp lamp = new Lamp();
    TRADE.registerAllServices(lamp, "hooked");
    Runtime.getRuntime().addShutdownHook(new Thread(() -> {
      try {
        while (System.in.read() >= 0) {
          // The test closes our input when the shutdown has had its chance to close TRADE.
        }
        TRADE.deregister(lamp);
        System.out.println("DEREGISTERED");
      } catch (TRADEException | IOException | RuntimeException e) {
        System.out.println("FAILED " + e);
      }
      System.out.flush();
    }, "component-shutdown"));
    Await.until(Duration.ofSeconds(30), () -> !TRADE.getAvailableServices(
        new TRADEServiceConstraints().name("left")).isEmpty(), "the peer's service");
    System.out.println("READY");
    System.out.flush();
    System.exit(0);
  }
}
