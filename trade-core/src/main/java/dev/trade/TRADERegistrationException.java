package dev.trade;

/**
 * An object could not be registered (or deregistered): the message names the class and method and
 * says how to fix it.
 */
public class TRADERegistrationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADERegistrationException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADERegistrationException(String message, Throwable cause) {
    super(message, cause);
  }
}
