package dev.trade.internal.hooks;

import dev.trade.TRADEAccess;
import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemServices;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The system service of the call log and call statistics, one per container in the reserved
 * group: the call log is a set of asynchronous after hooks whose wrapper is this service's
 * {@link #logCall}; the statistics come from an observer of this container's host chain. Its
 * methods, their parameter and return types, are specified in docs/hooks.md.
 *
 * <p>Public only because services must be; the module does not export it. Safe for concurrent use.
 *
 * <p>Open to every caller ({@link TRADEAccess#ANYONE}), although it is in the reserved group, as the
 * notification and lock services are: containers use it on their users' behalf, without
 * credentials. An access file can restrict it by service name (docs/security.md).
 */
@TRADEAccess(TRADEAccess.ANYONE)
public final class CallLogService {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");

  private final Registry registry;
  private final HookClient client;
  private final HookLink link;
  private final CallStats stats = new CallStats();
  private final int defaultMaxBytes;
  private CallLog log; // Guarded by this.
  private Query covered; // Guarded by this: the targets of the running log's set hook.

  CallLogService(Registry registry, HookClient client, HookLink link, int defaultMaxBytes) {
    this.registry = registry;
    this.client = client;
    this.link = link;
    this.defaultMaxBytes = defaultMaxBytes;
  }

  /**
   * Starts the call log of this container: an asynchronous after hook on every service of the
   * groups (any of them; none: every service but the system services), in every container, now
   * and as they join; and this container's statistics.
   *
   * @param file the file to append JSON lines to; its directory must exist
   * @param groups the groups whose services are logged; empty: all
   * @param maxBytes the size at which the file is rotated; 0 or less: CALLLOGMAXBYTES
   * @return the file's absolute path
   * @throws TRADEException {@code TRADEBadArgumentsException} if a call log runs here already or
   *     the file cannot be opened (nothing started)
   */
  @TRADEService
  public synchronized String startCallLog(String file, List<String> groups, int maxBytes)
      throws TRADEException {
    if (log != null) {
      throw new TRADEBadArgumentsException("A call log runs in this container already (file "
          + log.file().path() + "); stop it first");
    }
    if (file == null || file.isBlank()) {
      throw new TRADEBadArgumentsException("A call log needs a file name");
    }
    CallLogFile f;
    try {
      f = new CallLogFile(Path.of(file), maxBytes > 0 ? maxBytes : defaultMaxBytes);
    } catch (IOException | RuntimeException e) {
      throw new TRADEBadArgumentsException("The call log cannot write " + file + ": " + e);
    }
    log = new CallLog(f, registry);
    covered = query(groups == null ? List.of() : groups);
    link.observe(stats);
    int n = client.addSet(Kind.AFTER_ASYNC, self(), covered);
    LOG.log(Level.INFO, "call log {0} started, covering {1} services now", f.path(), n);
    return f.path().toString();
  }

  /**
   * Stops the call log of this container and removes its hooks everywhere.
   *
   * @return whether one ran
   */
  @TRADEService
  public synchronized boolean stopCallLog() {
    if (log == null) {
      return false;
    }
    client.removeSet(Kind.AFTER_ASYNC, self(), covered);
    log.close();
    log = null;
    return true;
  }

  /** The wrapper of the call log's hooks: writes one line, if a call log runs. */
  @TRADEService
  public void logCall(Object[] call, Throwable failure, Map<String, Object> details) {
    CallLog l;
    synchronized (this) {
      l = log;
    }
    if (l != null && call != null && details != null) {
      l.log(call, failure, details);
    }
  }

  /** Switches this container's call statistics on or off (the counts so far stay). */
  @TRADEService
  public void setCallStatistics(boolean on) {
    link.observe(on ? stats : null);
  }

  /**
   * This container's call statistics: one map per service called since they were switched on,
   * keys as in docs/hooks.md.
   */
  @TRADEService
  public List<Map<String, Object>> callStatistics() {
    return stats.snapshot();
  }

  /** Stops the call log, if one runs, without removing hooks (the container is closing). */
  synchronized void close() {
    if (log != null) {
      log.close();
      log = null;
    }
  }

  private ServiceDescriptor self() {
    for (ServiceDescriptor d : SystemServices.everywhere(registry, "logCall")) {
      if (d.containerId().equals(registry.containerId())) {
        return d;
      }
    }
    throw new IllegalStateException("logCall is not registered in " + registry.containerId());
  }

  /** Services in any of {@code groups}; every ordinary service when there are none. */
  private static Query query(List<String> groups) {
    List<Query> others = new ArrayList<>();
    for (int i = 1; i < groups.size(); i++) {
      others.add(inGroup(groups.get(i), List.of()));
    }
    return groups.isEmpty() ? inGroup(null, List.of()) : inGroup(groups.get(0), others);
  }

  private static Query inGroup(String group, List<Query> alternatives) {
    return new Query(null, null, null, group == null ? Set.of() : Set.of(group), Set.of(), false,
        null, null, Set.of(), alternatives, List.of());
  }
}
