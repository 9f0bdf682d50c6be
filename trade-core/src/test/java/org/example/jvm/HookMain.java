package org.example.jvm;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.time.Duration;
import java.util.Arrays;

/**
 * A container in a process of its own that hooks a service of another process: it waits for the
 * service named by its first argument, puts its own {@code seenBefore} and {@code seenAfter} on it,
 * and prints {@code HOOKED}, then {@code BEFORE <array>} and {@code AFTER <array>} at every call of
 * the target. The other arguments are {@code KEY=VALUE} settings. Runs until its standard input
 * ends or it is killed.
 */
public final class HookMain {
  private HookMain() {}

  public static void main(String[] args) throws Exception {
    try (TRADEContainer container =
        RobotPartMain.builder(Arrays.copyOfRange(args, 1, args.length)).build()) {
      container.registerAllServices(new Observer(), "observers");
      TRADEServiceInfo target = container.waitForService(
          new TRADEServiceConstraints().name(args[0]), Duration.ofSeconds(30));
      container.beforeService(container.getAvailableService(
          new TRADEServiceConstraints().name("seenBefore")), target);
      container.afterService(container.getAvailableService(
          new TRADEServiceConstraints().name("seenAfter")), target);
      System.out.println("HOOKED");
      System.out.flush();
      while (System.in.read() >= 0) {
        // Input only tells us when to stop.
      }
    }
    System.exit(0);
  }

  public static final class Observer {
    @TRADEService
    public void seenBefore(Object[] call) {
      System.out.println("BEFORE " + Arrays.deepToString(call));
      System.out.flush();
    }

    @TRADEService
    public void seenAfter(Object[] call) {
      System.out.println("AFTER " + Arrays.deepToString(call));
      System.out.flush();
    }
  }
}
