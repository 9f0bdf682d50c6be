package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import java.lang.management.ManagementFactory;

/**
 * The starting container of the lifecycle benchmark, in a fresh JVM: builds a container with
 * multicast discovery on loopback and one service in group {@code args[2]}, prints
 * {@code BUILT <before-build> <after-register> <jvm-start>} (epoch microseconds) and serves until
 * standard input closes or it is killed (at most 5 minutes).
 */
public final class ProviderMain {
  /** The service the peer calls. */
  public static final class Probe {
    @TRADEService
    public boolean lifecyclePing(int x) {
      return (x & 1) == 0;
    }
  }

  private ProviderMain() {}

  public static void main(String[] args) throws Exception {
    String sysId = args[0];
    String port = args[1];
    String group = args[2];
    long jvmStart = ManagementFactory.getRuntimeMXBean().getStartTime() * 1000;
    // Outside the timed part: the JVM's first string concatenation spins classes of its own, and
    // this program's concatenation is not TRADE's.
    String name = "provider-" + group;
    long before = Clock.epochMicros();
    TRADEContainer c = Lifecycle.discovering(TRADEContainer.builder().name(name), sysId, port)
        .build();
    c.registerAllServices(new Probe(), group);
    long after = Clock.epochMicros();
    // Not +: this JVM's first concatenation of longs would spin method-handle classes on the main
    // thread while the container's threads link up, and the timed part goes on until the call.
    System.out.println(new StringBuilder("BUILT ").append(before).append(' ').append(after)
        .append(' ').append(jvmStart));
    System.out.flush();
    Thread watchdog = new Thread(() -> {
      try {
        Thread.sleep(5 * 60_000L);
      } catch (InterruptedException e) {
        return;
      }
      Runtime.getRuntime().halt(3);
    });
    watchdog.setDaemon(true);
    watchdog.start();
    while (System.in.read() >= 0) {
      // Serve until the parent closes our input.
    }
    c.close();
    System.exit(0);
  }
}
