package dev.trade;

/**
 * The service was known but is not available any longer: it was deregistered, or its container left or
 * died. The message starts with {@code "Service not available any longer"}, as existing code expects.
 */
public class TRADEServiceUnavailableException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADEServiceUnavailableException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADEServiceUnavailableException(String message, Throwable cause) {
    super(message, cause);
  }
}
