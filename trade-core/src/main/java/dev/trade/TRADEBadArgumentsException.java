package dev.trade;

/**
 * The arguments or the requested return type do not fit the service's signature; the message names
 * the parameter (index, name, expected type). Nothing was invoked.
 */
public class TRADEBadArgumentsException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADEBadArgumentsException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADEBadArgumentsException(String message, Throwable cause) {
    super(message, cause);
  }
}
