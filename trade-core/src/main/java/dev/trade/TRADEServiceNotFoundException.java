package dev.trade;

/**
 * No service matches the given constraints, or an object to deregister is not registered.
 */
public class TRADEServiceNotFoundException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADEServiceNotFoundException(String message) {
    super(message);
  }

  public TRADEServiceNotFoundException(String message, Throwable cause) {
    super(message, cause);
  }
}
