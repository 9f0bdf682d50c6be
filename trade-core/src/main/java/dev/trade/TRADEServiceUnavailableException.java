package dev.trade;

/**
 * The service was known but is not available any longer: it was deregistered, or its container left or
 * died. The message starts with {@code "Service not available any longer"}, as existing code expects.
 */
public class TRADEServiceUnavailableException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADEServiceUnavailableException(String message) {
    super(message);
  }

  public TRADEServiceUnavailableException(String message, Throwable cause) {
    super(message, cause);
  }
}
