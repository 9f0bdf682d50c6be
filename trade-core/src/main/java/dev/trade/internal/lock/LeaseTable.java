package dev.trade.internal.lock;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADENotAuthorizedException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * The leases on the services of one container, its queue of waiting lock requests and the latest
 * fencing token of each service; every decision takes {@code now} ({@link System#nanoTime()}
 * units). Safe for concurrent use: guarded by its own monitor, on which waiting requests and calls
 * wait ({@link #awaitGrant}, {@link #awaitAdmission}).
 */
final class LeaseTable {
  /** Who asks: a lock, the container that owns it, the principal it acts for. */
  record Claim(UUID lock, UUID owner, String principal) {}

  /**
   * What keeps a request or a call out: the service, the claim in its way, since when (epoch ms),
   * and whether that claim holds the service (false: it waits for it, ahead of the request).
   */
  record Blocker(long service, Claim claim, long sinceMillis, boolean holding) {}

  /**
   * A grant (tokens by service, in request order) or the blocker that prevented it; neither for a
   * request withdrawn because its owner left ({@link #WITHDRAWN}).
   */
  record Outcome(Map<Long, Long> tokens, Blocker blocker) {
    static final Outcome WITHDRAWN = new Outcome(null, null);

    boolean granted() {
      return tokens != null;
    }
  }

  /**
   * Whether a call may run: {@code why} is null when it may; otherwise {@code blocker} is the
   * lease in its way (null when none is, e.g. the call's lock holds nothing here) and
   * {@code mayWait} tells whether a call that asked to wait should (another lock holds it).
   */
  record Admission(String why, Blocker blocker, boolean mayWait) {
    static final Admission OK = new Admission(null, null, false);

    boolean admitted() {
      return why == null;
    }
  }

  /** One row of {@link #list}: a lease on a service, or a request waiting for it. */
  record Row(long service, Claim claim, long sinceMillis, boolean holding, long token,
      long expiresInNanos) {}

  private static final class Lease {
    final Claim claim;
    final long sinceMillis;
    final Map<Long, Long> tokens = new LinkedHashMap<>();
    long expiresAt;

    Lease(Claim claim, long sinceMillis, long expiresAt) {
      this.claim = claim;
      this.sinceMillis = sinceMillis;
      this.expiresAt = expiresAt;
    }
  }

  private record Waiter(long ticket, Claim claim, long[] services, long sinceMillis) {}

  private final long leaseNanos;
  private final Map<Long, Lease> holders = new HashMap<>(); // Guarded by this.
  private final Map<UUID, Lease> leases = new HashMap<>(); // Guarded by this.
  private final Map<Long, Long> latest = new HashMap<>(); // Guarded by this.
  private final TreeMap<Long, Waiter> waiters = new TreeMap<>(); // Guarded by this.
  private long nextToken; // Guarded by this.
  private long nextTicket; // Guarded by this.
  /** Whether any service ever had a lease here: until then a call needs no look at the table. */
  private volatile boolean used;

  /** @param leaseNanos how long a lease lasts after its grant or last renewal; positive */
  LeaseTable(long leaseNanos) {
    if (leaseNanos <= 0) {
      throw new IllegalArgumentException("leaseNanos must be positive: " + leaseNanos);
    }
    this.leaseNanos = leaseNanos;
  }

  long leaseNanos() {
    return leaseNanos;
  }

  /** Whether no service was ever leased here (then every call without a lock may run). */
  boolean unused() {
    return !used;
  }

  /** Queues a request for {@code services}; its ticket orders it after every earlier one. */
  synchronized long enqueue(Claim claim, long[] services, long sinceMillis) {
    long ticket = ++nextTicket;
    waiters.put(ticket, new Waiter(ticket, claim, services.clone(), sinceMillis));
    return ticket;
  }

  /** Takes request {@code ticket} out of the queue (granted, refused or given up). */
  synchronized void leave(long ticket) {
    if (waiters.remove(ticket) != null) {
      notifyAll(); // requests behind it may be granted now
    }
  }

  /**
   * Grants {@code services} to {@code claim} if none is leased and no request queued before
   * {@code ticket} waits for one of them (pass {@link Long#MAX_VALUE} for a request not queued:
   * then every queued request comes first). All or nothing.
   *
   * @throws TRADEBadArgumentsException if the lock already holds a lease here
   */
  synchronized Outcome tryGrant(Claim claim, long[] services, long ticket, long now,
      long nowMillis) throws TRADEBadArgumentsException {
    expire(now);
    if (leases.containsKey(claim.lock())) {
      throw new TRADEBadArgumentsException("Lock " + claim.lock() + " already holds services in this"
          + " container; a lock is taken once: use a new lock id");
    }
    for (long s : services) {
      Lease h = holders.get(s);
      if (h != null) {
        return new Outcome(null, new Blocker(s, h.claim, h.sinceMillis, true));
      }
    }
    for (Waiter w : waiters.headMap(ticket, false).values()) {
      for (long s : services) {
        if (contains(w.services, s)) {
          return new Outcome(null, new Blocker(s, w.claim, w.sinceMillis, false));
        }
      }
    }
    Lease lease = new Lease(claim, nowMillis, now + leaseNanos);
    for (long s : services) {
      long token = ++nextToken;
      latest.put(s, token);
      holders.put(s, lease);
      lease.tokens.put(s, token);
    }
    leases.put(claim.lock(), lease);
    used = true;
    return new Outcome(Map.copyOf(lease.tokens), null);
  }

  /**
   * Queues the request and waits until it is granted or {@code deadline} passes; waking at every
   * release and at the next expiry. Reads time from {@code clock} (nanoseconds) and
   * {@code wall} (epoch ms).
   */
  Outcome awaitGrant(Claim claim, long[] services, long deadline, LongSupplier clock,
      LongSupplier wall) throws TRADEBadArgumentsException, InterruptedException {
    long ticket = enqueue(claim, services, wall.getAsLong());
    try {
      synchronized (this) {
        while (true) {
          if (!waiters.containsKey(ticket)) {
            return Outcome.WITHDRAWN; // its owner left: a grant would hold services for no one
          }
          long now = clock.getAsLong();
          Outcome o = tryGrant(claim, services, ticket, now, wall.getAsLong());
          if (o.granted() || deadline - now <= 0) {
            return o;
          }
          TimeUnit.NANOSECONDS.timedWait(this, wakeUp(now, deadline));
        }
      }
    } finally {
      leave(ticket);
    }
  }

  /** Nanoseconds to wait from {@code now}: until {@code deadline} or the next expiry. */
  private long wakeUp(long now, long deadline) {
    long until = deadline;
    for (Lease l : leases.values()) {
      if (l.expiresAt - until < 0) {
        until = l.expiresAt;
      }
    }
    return Math.max(1, until - now);
  }

  /**
   * Pushes the expiry of {@code owner}'s leases among {@code locks} to {@code now} plus the lease.
   *
   * @return for each of those locks still held here (by {@code owner}), the services it holds
   */
  synchronized Map<UUID, long[]> renew(UUID owner, List<UUID> locks, long now) {
    expire(now);
    Map<UUID, long[]> held = new LinkedHashMap<>();
    for (UUID id : locks) {
      Lease l = leases.get(id);
      if (l != null && l.claim.owner().equals(owner)) {
        l.expiresAt = now + leaseNanos;
        long[] services = new long[l.tokens.size()];
        int i = 0;
        for (long s : l.tokens.keySet()) {
          services[i++] = s;
        }
        held.put(id, services);
      }
    }
    return held;
  }

  /**
   * Ends lock {@code lock}'s lease here.
   *
   * @return how many services it held here (0: none, or its lease had ended)
   * @throws TRADENotAuthorizedException if another container owns the lock; nothing changes
   */
  synchronized int release(UUID lock, UUID caller, long now) throws TRADENotAuthorizedException {
    expire(now);
    Lease l = leases.get(lock);
    if (l == null) {
      return 0;
    }
    if (!l.claim.owner().equals(caller)) {
      throw new TRADENotAuthorizedException("Lock " + lock + " is owned by container "
          + l.claim.owner() + ", not by container " + caller + "; only its owner releases it");
    }
    remove(l);
    return l.tokens.size();
  }

  /**
   * Ends every lease of locks owned by container {@code owner}, which was seen to leave (closed,
   * crashed, or cut off): its renewals cannot arrive, so waiting for the leases to expire would
   * only keep the services idle. Requests of other owners waiting for them are woken, and the
   * owner's own waiting requests are withdrawn (they end not granted). A lease of an owner that is
   * merely slow is untouched: only its expiry ends it.
   *
   * @return how many leases ended
   */
  synchronized int ownerLeft(UUID owner, long now) {
    expire(now);
    List<Lease> ended = new ArrayList<>();
    for (Lease l : leases.values()) {
      if (l.claim.owner().equals(owner)) {
        ended.add(l);
      }
    }
    ended.forEach(this::remove);
    if (waiters.values().removeIf(w -> w.claim.owner().equals(owner))) {
      notifyAll();
    }
    return ended.size();
  }

  /** Forgets {@code service} (it left): its lease no longer holds it. */
  synchronized void drop(long service) {
    Lease l = holders.remove(service);
    latest.remove(service);
    if (l != null) {
      l.tokens.remove(service);
      if (l.tokens.isEmpty()) {
        leases.remove(l.claim.lock());
      }
      notifyAll();
    }
  }

  /**
   * Whether a call from {@code caller} to {@code service} may run now: without a lock, if no lease
   * holds the service; under lock {@code lock} with fencing token {@code token} (null: a call
   * without a lock), if that lock's lease holds the service with that token and the call comes
   * from the lock's owner.
   */
  synchronized Admission admit(long service, UUID lock, long token, UUID caller, long now) {
    expire(now);
    Lease h = holders.get(service);
    Blocker b = h == null ? null : new Blocker(service, h.claim, h.sinceMillis, true);
    if (lock == null) {
      return h == null ? Admission.OK : new Admission("it is locked", b, true);
    }
    Long last = latest.get(service);
    String fence = last != null && token < last ? "; its fencing token " + token
        + " is older than the service's latest grant, " + last : "";
    if (h == null || !h.claim.lock().equals(lock)) {
      return new Admission("lock " + lock + " does not hold it (released, its lease expired, or"
          + " never granted here)" + fence, b, false);
    }
    long mine = h.tokens.get(service);
    if (token != mine) {
      return new Admission("the call's fencing token " + token + " is not the token of lock "
          + lock + " for it, " + mine + (token < mine ? " (older tokens are refused)" : ""), b,
          false);
    }
    if (!h.claim.owner().equals(caller)) {
      return new Admission("lock " + lock + " is owned by container " + h.claim.owner()
          + "; calls under it come from that container, this one came from " + caller, b, false);
    }
    return Admission.OK;
  }

  /**
   * As {@link #admit}, waiting while another lock holds the service (a call that asked to wait)
   * until it is free or {@code deadline} passes.
   */
  Admission awaitAdmission(long service, UUID lock, long token, UUID caller, long deadline,
      LongSupplier clock) throws InterruptedException {
    synchronized (this) {
      while (true) {
        long now = clock.getAsLong();
        Admission a = admit(service, lock, token, caller, now);
        if (a.admitted() || !a.mayWait() || deadline - now <= 0) {
          return a;
        }
        TimeUnit.NANOSECONDS.timedWait(this, wakeUp(now, deadline));
      }
    }
  }

  /** Every lease and waiting request, by service: the holder first, then waiters in order. */
  synchronized List<Row> list(long now) {
    expire(now);
    TreeMap<Long, List<Row>> byService = new TreeMap<>();
    for (Map.Entry<Long, Lease> e : holders.entrySet()) {
      Lease l = e.getValue();
      byService.computeIfAbsent(e.getKey(), k -> new ArrayList<>()).add(new Row(e.getKey(),
          l.claim, l.sinceMillis, true, l.tokens.get(e.getKey()), l.expiresAt - now));
    }
    for (Waiter w : waiters.values()) {
      for (long s : w.services) {
        byService.computeIfAbsent(s, k -> new ArrayList<>())
            .add(new Row(s, w.claim, w.sinceMillis, false, 0, 0));
      }
    }
    List<Row> rows = new ArrayList<>();
    for (List<Row> r : byService.values()) {
      rows.addAll(r);
    }
    return rows;
  }

  /** Ends every lease whose expiry is not after {@code now}. */
  private void expire(long now) {
    boolean ended = false;
    for (Iterator<Lease> it = leases.values().iterator(); it.hasNext(); ) {
      Lease l = it.next();
      if (l.expiresAt - now <= 0) {
        it.remove();
        holders.values().removeIf(h -> h == l);
        ended = true;
      }
    }
    if (ended) {
      notifyAll();
    }
  }

  private void remove(Lease l) {
    leases.remove(l.claim.lock());
    for (long s : l.tokens.keySet()) {
      holders.remove(s, l);
    }
    notifyAll();
  }

  private static boolean contains(long[] services, long s) {
    for (long x : services) {
      if (x == s) {
        return true;
      }
    }
    return false;
  }

  @Override
  public synchronized String toString() {
    return "LeaseTable[" + leases.size() + " leases, " + waiters.size() + " waiting, tokens to "
        + nextToken + ", " + Arrays.toString(holders.keySet().toArray()) + "]";
  }
}
