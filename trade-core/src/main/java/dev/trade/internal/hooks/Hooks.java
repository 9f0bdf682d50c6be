package dev.trade.internal.hooks;

import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import java.time.Duration;
import java.util.function.Function;

/**
 * Hooks in one container, assembled: the table, its host-chain link, the system service and the
 * requester's client. The container registers {@link #service()} in the reserved group and puts
 * {@link #link()} in its host chain. Safe for concurrent use.
 */
public final class Hooks {
  private final HookTable table;
  private final HookLink link;
  private final HookService service;
  private final HookClient client;

  /**
   * @param caller calls wrappers and other containers' hook services (this container)
   * @param timeout the longest a synchronous hook may delay a call (HOOKTIMEOUT)
   * @param systemTargets whether hooks may wrap this container's system services
   *     (HOOKSYSTEMSERVICES)
   */
  public Hooks(Registry registry, ServiceCaller caller, InfoBinding infos,
      Function<Object, Query> queries, Duration timeout, boolean systemTargets, String name) {
    this.table = new HookTable(registry.containerId());
    registry.addListener(table);
    this.link = new HookLink(table, caller, timeout.toNanos(), name);
    this.service = new HookService(table, registry, infos, systemTargets);
    this.client = new HookClient(registry, caller, infos, queries, name);
  }

  /** The link of the host chain, between locks and the invoker. */
  public CallLink link() {
    return link;
  }

  /** The system service to register in the reserved group. */
  public Object service() {
    return service;
  }

  /** The requester's side, behind the static API. */
  public HookClient client() {
    return client;
  }

  /** Stops the asynchronous hooks' pool and following joins; idempotent. */
  public void close() {
    client.close();
    link.close();
  }
}
