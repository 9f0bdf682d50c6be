package dev.trade;

import dev.trade.internal.lock.LockClient;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

/**
 * A lock on a set of services, taken by {@link TRADEContainer#lock(java.util.Collection, java.time.Duration)}:
 * while it is held, only calls made under it ({@link TRADEServiceInfo#call(UUID, Class, Object...)})
 * from the container that took it run those services; every other call is refused with
 * {@link TRADELockedException}, wherever it comes from. Release it with {@link #close()}, best in
 * try-with-resources:
 *
 * <pre>{@code
 * try (TRADELock lock = container.lock(List.of(leftLeg, rightLeg), Duration.ofSeconds(2))) {
 *   leftLeg.call(lock.getId(), void.class, 0.3);
 *   rightLeg.call(lock.getId(), void.class, 0.3);
 * }
 * }</pre>
 *
 * <p>A lock is a lease in each service's container, renewed by its container while it lives and
 * reaches them; if it dies or is cut off, the services are free again as soon as their containers
 * see it leave, and at the latest {@code FAILURETIMEOUT} after its last renewal (docs/locks.md). A service that leaves, or whose lease ended, is {@linkplain #getDropped()
 * dropped} from the lock. Safe for concurrent use.
 */
public final class TRADELock implements AutoCloseable {
  private static final Logger LOG = System.getLogger("dev.trade.lock");

  private final TRADEContainer container;
  private final LockClient client;
  private final LockClient.Held held;

  TRADELock(TRADEContainer container, LockClient client, LockClient.Held held) {
    this.container = container;
    this.client = client;
    this.held = held;
  }

  /**
   * The lock's id, which calls under it carry.
   *
   * @return the id, as {@link TRADE#lockServicesContainAll(java.util.Collection)} returns one
   */
  public UUID getId() {
    return held.id();
  }

  /**
   * The services the lock was granted, in the order it took them (container id, then service).
   *
   * @return an unmodifiable list of the services
   */
  public List<TRADEServiceInfo> getServices() {
    return bind(held.services());
  }

  /**
   * The services the lock lost since it was granted: they left (their container died or
   * deregistered them), or their lease ended (this container could not renew it in time).
   *
   * @return an unmodifiable list of the lost services, in the order taken; empty for none
   */
  public List<TRADEServiceInfo> getDropped() {
    return bind(held.dropped());
  }

  /**
   * Whether the lock was released (by {@link #release()}, {@link #close()} or
   * {@link TRADE#releaseLock(UUID)}).
   *
   * @return true once released
   */
  public boolean isReleased() {
    return held.isReleased();
  }

  /**
   * Releases the lock in every container that holds services for it.
   *
   * @throws TRADEException {@link TRADEBadArgumentsException} if it was released already
   */
  public void release() throws TRADEException {
    client.release(held.id());
  }

  /**
   * Releases the lock if it is held; never throws: a container that cannot be reached frees the
   * services when the lease ends there.
   */
  @Override
  public void close() {
    if (!held.isReleased()) {
      try {
        client.release(held.id());
      } catch (TRADEException e) {
        LOG.log(Level.DEBUG, "lock {0}: {1}", held.id(), e.getMessage());
      }
    }
  }

  private List<TRADEServiceInfo> bind(List<ServiceDescriptor> services) {
    List<TRADEServiceInfo> infos = new ArrayList<>(services.size());
    for (ServiceDescriptor d : services) {
      infos.add(container.bind(d));
    }
    return List.copyOf(infos);
  }

  /**
   * {@code lock <id> [services]}, for logs.
   *
   * @return a short description
   */
  @Override
  public String toString() {
    return "lock " + held.id() + " " + getServices();
  }
}
