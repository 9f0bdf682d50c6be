package dev.trade;

/**
 * The caller is not allowed to do what it asked: TRADE 1.1.1's type for a refused administrative
 * call. Thrown today when a container releases a lock that another container owns
 * ({@link TRADE#releaseLock(java.util.UUID)}); access control will report its refusals with it.
 */
public class TRADENotAuthorizedException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what was refused, and who may do it
   */
  public TRADENotAuthorizedException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what was refused, and who may do it
   * @param cause the failure behind this one, or null
   */
  public TRADENotAuthorizedException(String message, Throwable cause) {
    super(message, cause);
  }
}
