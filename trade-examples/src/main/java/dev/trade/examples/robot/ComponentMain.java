package dev.trade.examples.robot;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceInfo;
import dev.trade.examples.ExampleContainers;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.StringJoiner;
import java.util.concurrent.CountDownLatch;

/**
 * Runs one robot component in this JVM, in a container of its own:
 *
 * <pre>
 * java -cp CLASSPATH dev.trade.examples.robot.ComponentMain --component arm|head|vision|nav|battery|planner|lookout
 *     [--name NAME] [--groups G1,G2] [--config FILE] [--call-log FILE] [--verbose]
 * </pre>
 *
 * <ul>
 *   <li>{@code --component}: what to run. The parts register their services and print
 *       {@code ready: ...}; they then serve until the process is stopped. The planner runs its
 *       scenario ({@link Planner}) and exits with status 0 when it was completed, 1 when not.
 *   <li>{@code --name}: the container's name (default: the component's).
 *   <li>{@code --groups}: the groups the part registers its services in, or the groups whose
 *       services the planner uses (default {@code MyRobot}).
 *   <li>{@code --config}: a {@code trade.properties}; without it, TRADE's usual resolution
 *       ({@code -Dtrade.properties.path}, {@code TRADE_PROPERTIES_PATH}, class path, defaults).
 *   <li>{@code --call-log}: write a call log of every call of the groups' services, in every
 *       container, to FILE (JSON lines; docs/hooks.md).
 *   <li>{@code --verbose}: also print TRADE's INFO log lines (links, discovery).
 * </ul>
 *
 * Exit status 2 means bad options or configuration.
 */
public final class ComponentMain {
  private static final List<String> KINDS = List.of("arm", "head", "vision", "nav", "battery", "planner",
      "lookout");

  private ComponentMain() {}

  public static void main(String[] args) throws InterruptedException {
    String kind = null;
    String name = null;
    List<String> groups = List.of("MyRobot");
    Path config = null;
    String callLog = null;
    boolean verbose = false;
    try {
      for (int i = 0; i < args.length; i++) {
        switch (args[i]) {
          case "--component" -> kind = value(args, ++i);
          case "--name" -> name = value(args, ++i);
          case "--groups" -> groups = groups(value(args, ++i));
          case "--config" -> config = Path.of(value(args, ++i));
          case "--call-log" -> callLog = value(args, ++i);
          case "--verbose" -> verbose = true;
          case "--help" -> {
            System.out.println(usage());
            return;
          }
          default -> throw new IllegalArgumentException("unknown option " + args[i]);
        }
      }
      if (kind == null || !KINDS.contains(kind)) {
        throw new IllegalArgumentException(kind == null ? "--component is missing"
            : "unknown component '" + kind + "'; one of " + KINDS);
      }
    } catch (IllegalArgumentException e) {
      System.err.println(e.getMessage() + "\n" + usage());
      System.exit(2);
    }
    ExampleContainers.configureLogging(verbose);
    TRADEContainer trade;
    try {
      trade = ExampleContainers.start(name == null ? kind : name, config);
    } catch (IllegalArgumentException e) {
      System.err.println(e.getMessage());
      System.exit(2);
      return;
    }
    if (callLog != null) {
      try {
        System.out.println("call log: " + trade.startCallLog(callLog, groups.toArray(new String[0])));
      } catch (TRADEException e) {
        System.err.println("cannot start the call log: " + e.getMessage());
        System.exit(2);
      }
    }
    if (kind.equals("lookout")) {
      boolean done = new Lookout(trade, groups, System.out).run();
      trade.close();
      System.exit(done ? 0 : 1);
    }
    if (kind.equals("planner")) {
      boolean done = new Planner(trade, groups, System.out).run();
      trade.close();
      System.exit(done ? 0 : 1);
    }
    try {
      Collection<TRADEServiceInfo> services = trade.registerAllServices(part(kind, System.out), groups);
      System.out.println("ready: " + names(services) + " in " + groups + " on " + trade.getName());
    } catch (TRADEException e) {
      System.err.println("cannot register the " + kind + ": " + e.getMessage());
      System.exit(1);
    }
    // Serve until the process is stopped; the shutdown hook closes the container.
    new CountDownLatch(1).await();
  }

  /** A new part of the given kind (not the planner). */
  static Object part(String kind, PrintStream out) {
    return switch (kind) {
      case "arm" -> new RobotArm(out);
      case "head" -> new Head(out);
      case "vision" -> new Camera(out);
      case "nav" -> new MobileBase(out);
      case "battery" -> new BatteryMonitor(97);
      default -> throw new IllegalArgumentException("not a part: " + kind);
    };
  }

  private static String value(String[] args, int i) {
    if (i >= args.length || args[i].startsWith("--")) {
      throw new IllegalArgumentException(args[i - 1] + " needs a value");
    }
    return args[i];
  }

  private static List<String> groups(String list) {
    List<String> result = new ArrayList<>();
    for (String g : list.split(",")) {
      if (!g.isBlank()) {
        result.add(g.trim());
      }
    }
    return result;
  }

  private static String names(Collection<TRADEServiceInfo> services) {
    StringJoiner j = new StringJoiner(", ");
    for (TRADEServiceInfo s : services) {
      j.add(s.serviceString);
    }
    return j.toString();
  }

  private static String usage() {
    return "usage: ComponentMain --component " + String.join("|", KINDS)
        + " [--name NAME] [--groups G1,G2] [--config FILE] [--call-log FILE] [--verbose]";
  }
}
