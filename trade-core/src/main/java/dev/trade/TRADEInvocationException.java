package dev.trade;

/**
 * The service itself threw. {@link #getCause()} is the exception it threw (rebuilt as its own class
 * when it came from another container and the class is known here).
 */
public class TRADEInvocationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADEInvocationException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADEInvocationException(String message, Throwable cause) {
    super(message, cause);
  }
}
