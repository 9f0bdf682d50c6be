package dev.trade;

/**
 * The caller is not allowed to do what it asked: TRADE 1.1.1's type for a refused administrative
 * call. This version has no access control yet (every operation is open), so nothing throws it
 * today; it exists so that code catching it compiles, and access control will report refusals with
 * it.
 */
public class TRADENotAuthorizedException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADENotAuthorizedException(String message) {
    super(message);
  }

  public TRADENotAuthorizedException(String message, Throwable cause) {
    super(message, cause);
  }
}
