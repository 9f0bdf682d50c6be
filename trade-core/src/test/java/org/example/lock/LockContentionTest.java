package org.example.lock;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Lockers of overlapping sets of joints in three containers, each taking, using and releasing its
 * set 1,000 times: never two inside one joint at once, no locker stuck (every one finishes, each
 * waiting as long as it takes), whatever the interleaving.
 */
class LockContentionTest {
  private static final int ROUNDS = 1000;
  private static final int JOINTS_PER_CONTAINER = 2;

  @RegisterExtension final Hubs net = new Hubs();

  @Test
  void twoLockers() throws Exception {
    contend(2);
  }

  @Test
  void eightLockers() throws Exception {
    contend(8);
  }

  private void contend(int lockers) throws Exception {
    TRADEContainer a = net.hub("a");
    List<TRADEContainer> containers = List.of(a, net.spoke("b", a), net.spoke("c", a));
    List<Joint> joints = new ArrayList<>();
    int n = 0;
    for (TRADEContainer x : containers) {
      for (int i = 0; i < JOINTS_PER_CONTAINER; i++) {
        Joint j = new Joint();
        joints.add(j);
        x.registerAllServices(j, "joint" + n++);
      }
    }
    int total = n;
    for (TRADEContainer x : containers) {
      Await.until(Duration.ofSeconds(30), () -> x.getAvailableServices(
          new TRADEServiceConstraints().name("enter")).size() == total, x.getName() + " sees all");
    }
    ExecutorService pool = Executors.newFixedThreadPool(lockers);
    try {
      List<Future<Integer>> done = new ArrayList<>();
      for (int l = 0; l < lockers; l++) {
        TRADEContainer owner = containers.get(l % containers.size());
        String me = "locker" + l;
        Random random = new Random(l);
        done.add(pool.submit(() -> {
          for (int r = 0; r < ROUNDS; r++) {
            round(owner, me, pick(random, total));
          }
          return ROUNDS;
        }));
      }
      for (Future<Integer> f : done) {
        // Generous: a stuck locker fails here, not by the machine's speed.
        assertEquals(ROUNDS, f.get(10, TimeUnit.MINUTES), "every locker finishes");
      }
    } finally {
      pool.shutdownNow();
    }
    int overlaps = 0;
    for (Joint j : joints) {
      overlaps += j.overlaps.get();
    }
    assertEquals(0, overlaps, "never two lockers inside one joint");
    for (TRADEContainer x : containers) {
      assertEquals(List.of(), x.getLocks(), "nothing left locked");
    }
  }

  /** Two or three of the joints, overlapping other lockers' picks. */
  private static List<Integer> pick(Random random, int total) {
    List<Integer> picked = new ArrayList<>();
    int size = 2 + random.nextInt(2);
    while (picked.size() < size) {
      int j = random.nextInt(total);
      if (!picked.contains(j)) {
        picked.add(j);
      }
    }
    return picked;
  }

  private static void round(TRADEContainer owner, String me, List<Integer> picked) throws Exception {
    List<TRADEServiceInfo> services = new ArrayList<>();
    for (int j : picked) {
      services.addAll(owner.getAvailableServices(new TRADEServiceConstraints().inGroups("joint" + j)));
    }
    try (TRADELock lock = owner.lock(services, Duration.ofMinutes(5))) {
      for (TRADEServiceInfo s : lock.getServices()) {
        if (s.serviceName.equals("enter")) {
          s.call(lock.getId(), void.class, me);
        }
      }
      for (TRADEServiceInfo s : lock.getServices()) {
        if (s.serviceName.equals("leave")) {
          s.call(lock.getId(), void.class, me);
        }
      }
    }
  }
}
