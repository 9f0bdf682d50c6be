package dev.trade;

/**
 * An object could not be registered (or deregistered): the message names the class and method and
 * says how to fix it.
 */
public class TRADERegistrationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADERegistrationException(String message) {
    super(message);
  }

  public TRADERegistrationException(String message, Throwable cause) {
    super(message, cause);
  }
}
