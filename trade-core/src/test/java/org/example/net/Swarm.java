package org.example.net;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import java.util.List;
import java.util.concurrent.ThreadLocalRandom;

/** Containers of a system of their own that find each other by multicast on loopback. */
final class Swarm {
  private final String port = Integer.toString(20_000 + ThreadLocalRandom.current().nextInt(20_000));
  private final String system = "swarm-" + Long.toHexString(ThreadLocalRandom.current().nextLong());

  private Swarm() {}

  /**
   * Builds {@code n} containers named c0, c1, ... into {@code into}, each providing {@link Named},
   * in a new system on a random port.
   */
  static Swarm start(int n, List<TRADEContainer> into) throws TRADEException {
    Swarm swarm = new Swarm();
    for (int i = 0; i < n; i++) {
      into.add(swarm.join("c" + i));
    }
    return swarm;
  }

  /** Builds one more container of this system, providing {@link Named}. */
  TRADEContainer join(String name) throws TRADEException {
    TRADEContainer c = TRADEContainer.builder().name(name)
        .property("STARTDISCOVERY", "true").property("STARTBROADCAST", "true")
        .property("BROADCASTPORT", port).property("TRADESYSID", system).build();
    c.registerAllServices(new Named(c.getName()));
    return c;
  }
}
