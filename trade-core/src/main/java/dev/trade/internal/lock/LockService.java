package dev.trade.internal.lock;

import dev.trade.TRADEAccess;
import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEService;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.CurrentCall;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.system.SystemGroup;
import dev.trade.TRADEServiceUnavailableException;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * The system service of locks, one per container in the reserved group: it leases this
 * container's services to locks, renews, releases and lists them. The owner of every request is
 * the container the call came from (the CALL's source), never an argument. Its methods, their
 * parameter and return types, are specified in docs/locks.md so that other implementations can
 * provide and call them.
 *
 * <p>Public only because services must be; the module does not export it. Safe for concurrent use.
 *
 * <p>Open to every caller ({@link TRADEAccess#ANYONE}), although it is in the reserved group: every
 * container takes locks on its users' behalf, without credentials; the service itself refuses a
 * release by a container that does not own the lock, and the owner is always the calling container.
 */
@TRADEAccess(TRADEAccess.ANYONE)
public final class LockService {
  private final LeaseTable table;
  private final Registry registry;
  private final InfoBinding infos;
  private final LongSupplier clock;
  private final LongSupplier wall;
  private final Locks.Names names;
  private final UUID self;

  LockService(LeaseTable table, Registry registry, InfoBinding infos, LongSupplier clock,
      LongSupplier wall, Locks.Names names) {
    this.table = table;
    this.registry = registry;
    this.infos = infos;
    this.clock = clock;
    this.wall = wall;
    this.names = names;
    this.self = UUID.fromString(registry.containerId());
  }

  /**
   * Leases services of this container to lock {@code lockId}, all or none, waiting up to
   * {@code waitMillis} (and the call's deadline) for them to be free; requests wait first come,
   * first served per service.
   *
   * @param lockId the lock's id, a UUID in canonical text, new for every lock
   * @param serviceIds the services' ids in this container; at least one, each once
   * @param waitMillis the longest wait; 0 to refuse at once when any is held or awaited
   * @return {@code granted} (Boolean); when granted, {@code tokens} (long[], the fencing token of
   *     each service, in the order asked); otherwise {@code reason} (String, who holds what)
   * @throws TRADEException {@code TRADEBadArgumentsException} for a malformed request or a lock id
   *     that holds services here already, {@code TRADEServiceUnavailableException} for a service
   *     not registered here; nothing is leased then
   */
  @TRADEService
  public Map<String, Object> lock(String lockId, long[] serviceIds, long waitMillis)
      throws TRADEException {
    UUID lock = parse(lockId, "lockId");
    if (serviceIds == null || serviceIds.length == 0) {
      throw new TRADEBadArgumentsException("lock: serviceIds is empty; a lock needs at least one"
          + " service");
    }
    if (waitMillis < 0) {
      throw new TRADEBadArgumentsException("lock: waitMillis is " + waitMillis + "; pass 0 or more");
    }
    Set<Long> seen = new HashSet<>();
    for (long id : serviceIds) {
      if (!seen.add(id)) {
        throw new TRADEBadArgumentsException("lock: serviceIds names service " + id + " twice");
      }
      LocalService s = registry.local(id);
      if (s == null || !s.isActive()) {
        throw new TRADEServiceUnavailableException(CallErrors.goneText("service " + id
            + " is not registered in container " + registry.containerId() + "; nothing was locked"));
      }
      if (s.descriptor().groups().contains(SystemGroup.NAME)) {
        throw new TRADEBadArgumentsException("lock: service " + s.descriptor().signature()
            + " is a system service (group " + SystemGroup.NAME + "); system services cannot be"
            + " locked");
      }
    }
    Invocation call = CurrentCall.get();
    LeaseTable.Claim claim = new LeaseTable.Claim(lock,
        call == null ? self : call.caller().container(), call == null ? "" : call.caller().principal());
    long now = clock.getAsLong();
    long deadline = now + TimeUnit.MILLISECONDS.toNanos(Math.min(waitMillis, Long.MAX_VALUE / 2_000_000));
    if (call != null && call.deadlineNanos() - deadline < 0) {
      deadline = call.deadlineNanos();
    }
    LeaseTable.Outcome o;
    if (waitMillis == 0) {
      o = table.tryGrant(claim, serviceIds, Long.MAX_VALUE, now, wall.getAsLong());
    } else {
      try {
        o = table.awaitGrant(claim, serviceIds, deadline, clock, wall);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        throw new TRADEException("lock: interrupted while waiting for services of container "
            + registry.containerId());
      }
    }
    Map<String, Object> result = new LinkedHashMap<>();
    result.put("granted", o.granted());
    if (o.granted()) {
      long[] tokens = new long[serviceIds.length];
      for (int i = 0; i < tokens.length; i++) {
        tokens[i] = o.tokens().get(serviceIds[i]);
      }
      result.put("tokens", tokens);
      result.put("leaseMillis", TimeUnit.NANOSECONDS.toMillis(table.leaseNanos()));
    } else {
      result.put("reason", o.blocker() == null
          ? "container " + claim.owner() + " left while its request waited"
          : names.describe(o.blocker()));
    }
    return result;
  }

  /**
   * Renews the calling container's leases of {@code lockIds} here, for another lease period.
   *
   * @param lockIds lock ids in canonical text
   * @return for each of those locks that still holds services here, its id and the ids of those
   *     services (long[]); a lock missing from it lost its lease here
   * @throws TRADEException {@code TRADEBadArgumentsException} if an id is not a UUID
   */
  @TRADEService
  public Map<String, Object> renew(List<String> lockIds) throws TRADEException {
    List<UUID> ids = new ArrayList<>();
    for (String id : lockIds == null ? List.<String>of() : lockIds) {
      ids.add(parse(id, "lockIds"));
    }
    Map<String, Object> held = new LinkedHashMap<>();
    for (Map.Entry<UUID, long[]> e : table.renew(owner(), ids, clock.getAsLong()).entrySet()) {
      held.put(e.getKey().toString(), e.getValue());
    }
    return held;
  }

  /**
   * Ends lock {@code lockId}'s lease here; calls under it are refused from now on.
   *
   * @return how many services it held here (0: none, or its lease had ended)
   * @throws TRADEException {@code TRADENotAuthorizedException} if another container owns it,
   *     {@code TRADEBadArgumentsException} if the id is not a UUID
   */
  @TRADEService
  public int release(String lockId) throws TRADEException {
    UUID lock = parse(lockId, "lockId");
    try {
      return table.release(lock, owner(), clock.getAsLong());
    } catch (TRADENotAuthorizedException e) {
      throw new TRADENotAuthorizedException(e.getMessage().replace("container " + owner(),
          "container " + names.containerName(owner())));
    }
  }

  /**
   * The leases and waiting requests of this container, by service: the holder first, then the
   * waiters in the order they will be served.
   *
   * @return one map each: {@code service} (the service info), {@code lock} (String),
   *     {@code container} (the owner's id, String), {@code containerName} (String),
   *     {@code principal} (String), {@code since} (Instant), {@code holding} (Boolean),
   *     {@code token} (Long; 0 for a waiter), {@code expiresInMillis} (Long; 0 for a waiter)
   */
  @TRADEService
  public List<Map<String, Object>> listLocks() {
    List<Map<String, Object>> rows = new ArrayList<>();
    for (LeaseTable.Row r : table.list(clock.getAsLong())) {
      LocalService s = registry.local(r.service());
      if (s == null) {
        continue;
      }
      Map<String, Object> m = new LinkedHashMap<>();
      m.put("service", infos.bind(s.descriptor()));
      m.put("lock", r.claim().lock().toString());
      m.put("container", r.claim().owner().toString());
      m.put("containerName", names.containerName(r.claim().owner()));
      m.put("principal", r.claim().principal());
      m.put("since", Instant.ofEpochMilli(r.sinceMillis()));
      m.put("holding", r.holding());
      m.put("token", r.token());
      m.put("expiresInMillis", TimeUnit.NANOSECONDS.toMillis(r.expiresInNanos()));
      rows.add(m);
    }
    return rows;
  }

  private UUID owner() {
    Invocation call = CurrentCall.get();
    return call == null ? self : call.caller().container();
  }

  private static UUID parse(String id, String parameter) throws TRADEBadArgumentsException {
    try {
      return UUID.fromString(id);
    } catch (RuntimeException e) {
      throw new TRADEBadArgumentsException(parameter + ": '" + id + "' is not a lock id (a UUID in"
          + " its canonical text)");
    }
  }
}
