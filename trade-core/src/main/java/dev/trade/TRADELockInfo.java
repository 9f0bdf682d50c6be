package dev.trade;

import java.time.Instant;
import java.util.Objects;
import java.util.UUID;

/**
 * One lock's claim on one service, as {@link TRADEContainer#getLocks()} reports it from any
 * container: the lock that holds the service, or one that waits for it. An immutable value, safe
 * for concurrent use.
 */
public final class TRADELockInfo {
  private final TRADEServiceInfo service;
  private final UUID lockId;
  private final String containerId;
  private final String containerName;
  private final String principal;
  private final Instant since;
  private final boolean holding;
  private final long fencingToken;

  TRADELockInfo(TRADEServiceInfo service, UUID lockId, String containerId, String containerName,
      String principal, Instant since, boolean holding, long fencingToken) {
    this.service = Objects.requireNonNull(service, "service == null");
    this.lockId = Objects.requireNonNull(lockId, "lockId == null");
    this.containerId = Objects.requireNonNull(containerId, "containerId == null");
    this.containerName = Objects.requireNonNull(containerName, "containerName == null");
    this.principal = Objects.requireNonNull(principal, "principal == null");
    this.since = Objects.requireNonNull(since, "since == null");
    this.holding = holding;
    this.fencingToken = fencingToken;
  }

  /**
   * The locked (or awaited) service.
   *
   * @return the service
   */
  public TRADEServiceInfo getService() {
    return service;
  }

  /**
   * The lock's id.
   *
   * @return the id of the lock that holds or waits for the service
   */
  public UUID getLockId() {
    return lockId;
  }

  /**
   * The container that owns the lock (took it, and renews it).
   *
   * @return its id
   */
  public String getContainerId() {
    return containerId;
  }

  /**
   * The name of the container that owns the lock, as the service's container knows it.
   *
   * @return its name, or its id when unknown there
   */
  public String getContainerName() {
    return containerName;
  }

  /**
   * The principal the lock was taken for.
   *
   * @return the principal; empty until access control gives callers one
   */
  public String getPrincipal() {
    return principal;
  }

  /**
   * Since when the lock holds the service, or since when it waits for it, by the service's
   * container's clock.
   *
   * @return the instant of the grant or of the request
   */
  public Instant getSince() {
    return since;
  }

  /**
   * Whether the lock holds the service (false: it waits for it).
   *
   * @return true for the holder
   */
  public boolean isHolding() {
    return holding;
  }

  /**
   * The fencing token of the grant: calls under the lock carry it, and the service's container
   * refuses older ones.
   *
   * @return the token, positive for a holder; 0 for a waiter
   */
  public long getFencingToken() {
    return fencingToken;
  }

  /**
   * {@code service held by lock <id> of <container> since <instant>}, for logs.
   *
   * @return a short description
   */
  @Override
  public String toString() {
    return service + (holding ? " held by" : " awaited by") + " lock " + lockId + " of "
        + containerName + (principal.isEmpty() ? "" : " (" + principal + ")") + " since " + since
        + (holding ? ", token " + fencingToken : "");
  }
}
