package dev.trade;

/**
 * The caller is not allowed to do what it asked: TRADE 1.1.1's type for a refused administrative
 * call. Thrown today when a container releases a lock that another container owns
 * ({@link TRADE#releaseLock(java.util.UUID)}); access control will report its refusals with it.
 */
public class TRADENotAuthorizedException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * A refusal that says what was refused and what was missing (never a secret).
   *
   * @param message the refusal
   */
  public TRADENotAuthorizedException(String message) {
    super(message);
  }

  /**
   * A refusal with its cause.
   *
   * @param message the refusal
   * @param cause why
   */
  public TRADENotAuthorizedException(String message, Throwable cause) {
    super(message, cause);
  }
}
