package dev.trade;

/**
 * The arguments or the requested return type do not fit the service's signature; the message names
 * the parameter (index, name, expected type). Nothing was invoked.
 */
public class TRADEBadArgumentsException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADEBadArgumentsException(String message) {
    super(message);
  }

  public TRADEBadArgumentsException(String message, Throwable cause) {
    super(message, cause);
  }
}
