package dev.trade;

/**
 * Base of every failure TRADE reports to a caller.
 *
 * <p>Callers that need to know what happened catch one of the subclasses rather than reading the
 * message: {@link TRADEServiceNotFoundException}, {@link TRADEServiceUnavailableException},
 * {@link TRADEInvocationException}, {@link TRADEBadArgumentsException},
 * {@link TRADETimeoutException}, {@link TRADERegistrationException},
 * {@link TRADESerializationException} and {@link TRADELockedException}.
 */
public class TRADEException extends Exception {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADEException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADEException(String message, Throwable cause) {
    super(message, cause);
  }
}
