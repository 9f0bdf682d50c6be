package dev.trade;

/**
 * Base of every failure TRADE reports to a caller.
 *
 * <p>Callers that need to know what happened catch one of the subclasses rather than reading the
 * message: {@link TRADEServiceNotFoundException}, {@link TRADEServiceUnavailableException},
 * {@link TRADEInvocationException}, {@link TRADEBadArgumentsException},
 * {@link TRADETimeoutException}, {@link TRADERegistrationException} and
 * {@link TRADESerializationException}.
 */
public class TRADEException extends Exception {
  private static final long serialVersionUID = 1L;

  public TRADEException(String message) {
    super(message);
  }

  public TRADEException(String message, Throwable cause) {
    super(message, cause);
  }
}
