package dev.trade.internal.hooks;

import dev.trade.TRADEException;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.Function;

/**
 * Hooks in one container, assembled: the table, its host-chain link, the system services (hooks,
 * call log) and the requester's client. The container registers {@link #services()} in the reserved group and puts
 * {@link #link()} in its host chain. Safe for concurrent use.
 */
public final class Hooks {
  private final HookTable table;
  private final HookLink link;
  private final HookService service;
  private final HookClient client;
  private final CallLogService callLog;

  /**
   * @param caller calls wrappers and other containers' hook services (this container)
   * @param timeout the longest a synchronous hook may delay a call (HOOKTIMEOUT)
   * @param systemTargets whether hooks may wrap this container's system services
   *     (HOOKSYSTEMSERVICES)
   * @param callLogMaxBytes the size at which call log files are rotated (CALLLOGMAXBYTES)
   */
  public Hooks(Registry registry, ServiceCaller caller, InfoBinding infos,
      Function<Object, Query> queries, Duration timeout, boolean systemTargets, int callLogMaxBytes,
      String name) {
    this.table = new HookTable(registry.containerId());
    registry.addListener(table);
    this.link = new HookLink(table, caller, timeout.toNanos(), name);
    this.service = new HookService(table, registry, infos, systemTargets);
    this.client = new HookClient(registry, caller, infos, queries, name);
    this.callLog = new CallLogService(registry, client, link, callLogMaxBytes);
  }

  /** The link of the host chain, between locks and the invoker. */
  public CallLink link() {
    return link;
  }

  /**
   * Whether {@code call} must pass the hooks link: false when it has no hooks, no hook path and
   * no observer, so that the container can run it through its chain without the link. Cheap: two
   * volatile reads and an empty-map check.
   */
  public boolean concerns(Invocation call) {
    return link.concerns(call);
  }

  /** The system services to register in the reserved group: hooks, and the call log. */
  public List<Object> services() {
    return List.of(service, callLog);
  }

  /**
   * Starts the call log, as the CALLLOG setting asks (once the system services are registered).
   *
   * @throws TRADEException if it cannot start (the message names the file)
   */
  public void startCallLog(String file, List<String> groups) throws TRADEException {
    callLog.startCallLog(file, groups, 0);
  }

  /**
   * This container's call statistics, as its {@code callStatistics} service returns them: empty
   * unless they are or were switched on.
   */
  public List<Map<String, Object>> statistics() {
    return callLog.callStatistics();
  }

  /** The requester's side, behind the static API. */
  public HookClient client() {
    return client;
  }

  /** Stops the asynchronous hooks' pool and following joins; idempotent. */
  public void close() {
    callLog.close();
    client.close();
    link.close();
  }
}
