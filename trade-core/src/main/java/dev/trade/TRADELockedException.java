package dev.trade;

/**
 * A call or a lock request was refused because of a lock: the service is held by another lock
 * (the message names it: its id, the container that owns it, its principal and since when), or the
 * call was made under a lock that does not hold the service (any more: released, its lease
 * expired, or its fencing token is older than the service's latest grant). A call that was refused
 * did not run. See docs/locks.md.
 *
 * <p>A call to a locked service fails with it at once, unless the call was made through
 * {@link TRADEServiceInfo#waitingForLock()}; a lock request fails with it when its services were
 * not all free within its longest wait.
 */
public class TRADELockedException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong: which service, which lock holds it, and how to go on
   */
  public TRADELockedException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong: which service, which lock holds it, and how to go on
   * @param cause the failure behind this one, or null
   */
  public TRADELockedException(String message, Throwable cause) {
    super(message, cause);
  }
}
