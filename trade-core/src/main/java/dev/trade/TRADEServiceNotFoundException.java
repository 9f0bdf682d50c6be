package dev.trade;

/**
 * No service matches the given constraints, or an object to deregister is not registered.
 */
public class TRADEServiceNotFoundException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADEServiceNotFoundException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADEServiceNotFoundException(String message, Throwable cause) {
    super(message, cause);
  }
}
