package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

/**
 * Locks, in one JVM over loopback: lock + unlock of 3 services in 3 containers from a fourth (the
 * owner), and a call under a lock against a plain call to the same remote service. Run:
 * {@code java -cp ... dev.trade.bench.LockBench [rounds]} inside {@code unshare --net}.
 */
public final class LockBench {
  private LockBench() {}

  /** One joint of a robot. */
  public static final class Joint {
    @TRADEService
    public int move(int degrees) {
      return degrees;
    }
  }

  public static void main(String[] args) throws Exception {
    int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 2000;
    try (TRADEContainer a = TRADEContainer.builder().name("a")
            .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0").build()) {
      String hub = a.getServerAddresses().get(0);
      try (TRADEContainer b = spoke("b", hub); TRADEContainer c = spoke("c", hub);
          TRADEContainer owner = spoke("owner", hub)) {
        a.registerAllServices(new Joint(), "joint");
        b.registerAllServices(new Joint(), "joint");
        c.registerAllServices(new Joint(), "joint");
        TRADEServiceConstraints joints = new TRADEServiceConstraints().inGroups("joint");
        long until = System.nanoTime() + Duration.ofSeconds(30).toNanos();
        while (owner.getAvailableServices(joints).size() < 3 && System.nanoTime() - until < 0) {
          LockSupport.parkNanos(1_000_000);
        }
        List<TRADEServiceInfo> three = new ArrayList<>(owner.getAvailableServices(joints));
        if (three.size() != 3) {
          throw new IllegalStateException("the owner sees " + three.size() + " joints, not 3");
        }
        TRADEServiceInfo one = three.get(0);

        long[] lockUnlock = new long[rounds];
        for (int w = 0; w < 2; w++) {
          for (int i = 0; i < rounds; i++) {
            long t0 = System.nanoTime();
            try (TRADELock l = owner.lock(three, Duration.ZERO)) {
              lockUnlock[i] = 0;
            }
            lockUnlock[i] = System.nanoTime() - t0;
          }
        }
        long[] plain = new long[rounds];
        long[] underLock = new long[rounds];
        try (TRADELock l = owner.lock(three, Duration.ZERO)) {
          for (int w = 0; w < 2; w++) {
            for (int i = 0; i < rounds; i++) {
              long t0 = System.nanoTime();
              one.call(l.getId(), int.class, 1);
              long t1 = System.nanoTime();
              underLock[i] = t1 - t0;
            }
          }
        }
        for (int w = 0; w < 2; w++) {
          for (int i = 0; i < rounds; i++) {
            long t0 = System.nanoTime();
            one.call(int.class, 1);
            plain[i] = System.nanoTime() - t0;
          }
        }
        System.out.println(line("lock+unlock of 3 services in 3 containers", lockUnlock));
        System.out.println("  round trips per container: 1 (lock) + 1 (release), in container-id"
            + " order; renewals: 1 per container per FAILURETIMEOUT/3 while held");
        System.out.println(line("call under a lock (remote)", underLock));
        System.out.println(line("plain call (remote, same service)", plain));
      }
    }
  }

  private static TRADEContainer spoke(String name, String hub) {
    return TRADEContainer.builder().name(name).property("CONNECTCONTAINERS", hub).build();
  }

  private static String line(String what, long[] nanos) {
    long[] s = nanos.clone();
    Arrays.sort(s);
    return String.format(Locale.ROOT, "%-45s p50 %8.1f us  p90 %8.1f us  p99 %8.1f us  (n=%d)",
        what, s[s.length / 2] / 1e3, s[s.length * 9 / 10] / 1e3, s[s.length * 99 / 100] / 1e3,
        s.length);
  }
}
