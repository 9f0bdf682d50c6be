package dev.trade;

/**
 * A value could not be copied or could not travel: its class is not encodable, not allowed by the
 * deserialization allow-list, or not known on the receiving side (the message names the class);
 * or the call or result is larger than a container on its way accepts (the message names the
 * limit, {@code MAXFRAMESIZE}, and the container).
 */
public class TRADESerializationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /**
   * An exception with a message.
   *
   * @param message what went wrong and, where known, how to fix it
   */
  public TRADESerializationException(String message) {
    super(message);
  }

  /**
   * An exception with a message and a cause.
   *
   * @param message what went wrong and, where known, how to fix it
   * @param cause the failure behind this one, or null
   */
  public TRADESerializationException(String message, Throwable cause) {
    super(message, cause);
  }
}
