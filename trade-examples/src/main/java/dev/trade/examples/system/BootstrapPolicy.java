package dev.trade.examples.system;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.time.Duration;

/**
 * The TRADE paper's bootstrap policy: a planner that lacks a vision service switches announcing
 * on, waits for a vision service to join, then switches announcing off again and uses it. The
 * switches are the planner container's own middleware services, called with an administrator's
 * credentials (docs/middleware-services.md).
 *
 * <p>Usage: {@code BootstrapPolicy [KEY=VALUE ...]}, each a TRADE setting of the planner's
 * container; its access file ({@code PRINCIPALSFILE}) must hold the principal whose credentials
 * ({@code <principal>:<secret>}) the environment variable {@code TRADE_ADMIN_CREDENTIALS} gives,
 * with the role {@code admin}. Start a vision component with {@code STARTDISCOVERY=true} (for
 * example {@code ComponentMain}) on the same host: it hears the announcement, links, and its
 * {@code checkFor} service joins. Prints {@code BROADCASTING}, {@code JOINED <container>},
 * {@code QUIET} and the detection; exits 1 if no vision service joined within 60 s.
 */
public final class BootstrapPolicy {
  private BootstrapPolicy() {}

  public static void main(String[] args) throws TRADEException {
    TRADEContainer.Builder builder = TRADEContainer.builder().name("planner");
    for (String a : args) {
      int eq = a.indexOf('=');
      if (eq < 0) {
        throw new IllegalArgumentException("'" + a + "': settings are KEY=VALUE");
      }
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    String credentials = System.getenv("TRADE_ADMIN_CREDENTIALS");
    try (TRADEContainer planner = builder.build()) {
      TRADEServiceConstraints vision = new TRADEServiceConstraints().name("checkFor")
          .argTypes(String.class);
      planner.setBroadcast(credentials, true);
      System.out.println("BROADCASTING");
      TRADEServiceInfo checkFor;
      try {
        checkFor = planner.waitForService(vision, Duration.ofSeconds(60));
      } finally {
        planner.setBroadcast(credentials, false); // whatever happened, stop announcing
      }
      System.out.println("JOINED " + checkFor.getContainerName());
      System.out.println("QUIET");
      System.out.println(checkFor.call(Object.class, "cup"));
    } catch (dev.trade.TRADETimeoutException e) {
      System.out.println("no vision service joined: " + e.getMessage());
      System.exit(1);
    }
  }
}
