package org.example.jvm;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A part of the TRADE paper's robot in a process of its own: {@code battery} provides
 * {@code isLowBattery()} (and {@code setLow(boolean)} to make it drop), {@code dock} provides
 * {@code dock()} and can cancel a notification by id from its own container. Arguments: the role,
 * then {@code KEY=VALUE} settings. Prints {@code READY <container id>}, and {@code DOCKED <n>} at
 * every dock; runs until its standard input ends or it is killed.
 */
public final class RobotPartMain {
  private RobotPartMain() {}

  public static void main(String[] args) throws Exception {
    try (TRADEContainer container = builder(Arrays.copyOfRange(args, 1, args.length)).build()) {
      container.registerAllServices(args[0].equals("battery") ? new Battery() : new Dock(container),
          "robot");
      System.out.println("READY " + container.getId());
      System.out.flush();
      while (System.in.read() >= 0) {
        // Input only tells us when to stop.
      }
    }
    System.exit(0);
  }

  /** A builder with the {@code KEY=VALUE} settings of a process's arguments. */
  static TRADEContainer.Builder builder(String... settings) {
    TRADEContainer.Builder builder = TRADEContainer.builder();
    for (String a : settings) {
      int eq = a.indexOf('=');
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    return builder;
  }

  public static final class Battery {
    private volatile boolean low;

    @TRADEService
    public boolean isLowBattery() {
      return low;
    }

    @TRADEService
    public boolean isOverheated() {
      return false;
    }

    @TRADEService
    public void setLow(boolean low) {
      this.low = low;
    }
  }

  public static final class Dock {
    private final TRADEContainer container;
    private final AtomicInteger docked = new AtomicInteger();

    Dock(TRADEContainer container) {
      this.container = container;
    }

    @TRADEService
    public void dock() {
      System.out.println("DOCKED " + docked.incrementAndGet());
      System.out.flush();
    }

    @TRADEService
    public int dockCount() {
      return docked.get();
    }

    /** Cancels a notification by its id, from this container. */
    @TRADEService
    public boolean cancelNotification(String id) throws TRADEException {
      return container.cancelNotification(id);
    }
  }
}
