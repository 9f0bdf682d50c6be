package dev.trade;

/**
 * The call's deadline passed before a reply arrived. The service may or may not have run.
 */
public class TRADETimeoutException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADETimeoutException(String message) {
    super(message);
  }

  public TRADETimeoutException(String message, Throwable cause) {
    super(message, cause);
  }
}
