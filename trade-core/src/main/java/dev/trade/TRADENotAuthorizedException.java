package dev.trade;

/**
 * The caller is not allowed to do what it asked: TRADE 1.1.1's type for a refused administrative
 * call. This version has no access control yet (every operation is open), so nothing throws it
 * today; it exists so that code catching it compiles, and access control will report refusals with
 * it.
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
