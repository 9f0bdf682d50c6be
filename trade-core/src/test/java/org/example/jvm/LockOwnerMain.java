package org.example.jvm;

import dev.trade.TRADEContainer;
import dev.trade.TRADELock;
import dev.trade.TRADEServiceConstraints;
import java.time.Duration;

/**
 * A process that takes a lock and holds it: builds a container from {@code KEY=VALUE} arguments,
 * waits until a service in group {@code head} is known, locks every such service, prints
 * {@code HELD <lock id>} and holds the lock until its standard input ends or it is killed.
 */
public final class LockOwnerMain {
  private LockOwnerMain() {}

  public static void main(String[] args) throws Exception {
    TRADEContainer.Builder builder = TRADEContainer.builder();
    for (String a : args) {
      int eq = a.indexOf('=');
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    try (TRADEContainer container = builder.build()) {
      TRADEServiceConstraints head = new TRADEServiceConstraints().inGroups("head");
      container.waitForService(head, Duration.ofSeconds(60));
      try (TRADELock lock = container.lock(head, Duration.ofSeconds(60))) {
        System.out.println("HELD " + lock.getId());
        System.out.flush();
        while (System.in.read() >= 0) {
          // Input only tells us when to stop.
        }
      }
    }
    System.exit(0);
  }
}
