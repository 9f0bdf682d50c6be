package org.example.net;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/** Containers of a system of their own that find each other by multicast on loopback. */
final class Swarm {
  private Swarm() {}

  /**
   * Builds {@code n} containers named c0, c1, ... into {@code into}, each providing {@link Named},
   * in a new system on a random port.
   */
  static void start(int n, List<TRADEContainer> into) throws TRADEException {
    String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
    String system = "swarm-" + Long.toHexString(ThreadLocalRandom.current().nextLong());
    for (int i = 0; i < n; i++) {
      TRADEContainer c = TRADEContainer.builder().name("c" + i)
          .property("STARTDISCOVERY", "true").property("STARTBROADCAST", "true")
          .property("BROADCASTPORT", port).property("TRADESYSID", system).build();
      into.add(c);
      c.registerAllServices(new Named(c.getName()));
    }
  }
}
