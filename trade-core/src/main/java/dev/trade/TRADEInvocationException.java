package dev.trade;

/**
 * The service itself threw. {@link #getCause()} is the exception it threw (rebuilt as its own class
 * when it came from another container and the class is known here).
 */
public class TRADEInvocationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADEInvocationException(String message) {
    super(message);
  }

  public TRADEInvocationException(String message, Throwable cause) {
    super(message, cause);
  }
}
