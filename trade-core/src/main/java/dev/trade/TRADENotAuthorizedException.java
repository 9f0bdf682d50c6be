package dev.trade;

/**
 * The caller is not allowed to do what it asked: TRADE 1.1.1's type for a refused administrative
 * call. The providing container's access control refuses with it before the call runs
 * (docs/security.md, "Access control"), and a container refuses with it a release of a lock that
 * another container owns ({@link TRADE#releaseLock(java.util.UUID)}). The message names what was
 * refused and what was missing (a role, a valid or fresh proof of a principal); it never holds a
 * secret.
 */
public class TRADENotAuthorizedException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * A refusal described by {@code message}.
   *
   * @param message what was refused and what was missing; never a secret
   */
  public TRADENotAuthorizedException(String message) {
    super(message);
  }

  /**
   * A refusal described by {@code message}, caused by {@code cause}.
   *
   * @param message what was refused and what was missing; never a secret
   * @param cause the failure behind it
   */
  public TRADENotAuthorizedException(String message, Throwable cause) {
    super(message, cause);
  }
}
