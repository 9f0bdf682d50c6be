package org.example.jvm;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import java.util.Arrays;
import java.util.Collection;
import java.util.Map;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * A container of its own JVM for the middleware-services tests: registers {@code graphAs} (the
 * container graph as this container sees it) in group {@code node-<name>}, and prints every line
 * of the audit logger as {@code AUDIT <text>}. Arguments: the name, then {@code KEY=VALUE}
 * settings. Prints {@code READY <container id>}; runs until its standard input ends.
 */
public final class AdminNodeMain {
  /** Kept so that the logger and its handler stay. */
  private static final Logger AUDIT = Logger.getLogger("dev.trade.audit");

  private AdminNodeMain() {}

  public static void main(String[] args) throws Exception {
    AUDIT.addHandler(new Handler() {
      @Override
      public void publish(LogRecord r) {
        String text = r.getParameters() == null ? r.getMessage()
            : java.text.MessageFormat.format(r.getMessage(), r.getParameters());
        System.out.println("AUDIT " + text);
        System.out.flush();
      }

      @Override
      public void flush() {}

      @Override
      public void close() {}
    });
    TRADEContainer.Builder builder = TRADEContainer.builder().name(args[0]);
    for (String a : Arrays.copyOfRange(args, 1, args.length)) {
      int eq = a.indexOf('=');
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    try (TRADEContainer container = builder.build()) {
      container.registerAllServices(new Node(container), "node-" + args[0]);
      System.out.println("READY " + container.getId());
      System.out.flush();
      while (System.in.read() >= 0) {
        // Input only tells us when to stop.
      }
    }
    System.exit(0);
  }

  /** A provider an administrator may start by class name (PROVIDERCLASSES names it). */
  public static final class Echo {
    @TRADEService
    public String upper(String s) {
      return s.toUpperCase(java.util.Locale.ROOT);
    }
  }

  public static final class Node {
    private final TRADEContainer container;

    Node(TRADEContainer container) {
      this.container = container;
    }

    @TRADEService
    public Map<String, Collection<String>> graphAs(String credentials) throws TRADEException {
      return container.getTRADEContainerGraph(credentials);
    }
  }
}
