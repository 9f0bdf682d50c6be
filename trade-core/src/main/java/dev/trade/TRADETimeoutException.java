package dev.trade;

/**
 * The call's deadline passed before a reply arrived. The service may or may not have run.
 */
public class TRADETimeoutException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADETimeoutException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADETimeoutException(String message, Throwable cause) {
    super(message, cause);
  }
}
