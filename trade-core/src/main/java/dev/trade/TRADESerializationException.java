package dev.trade;

/**
 * A value could not be copied or could not travel: its class is not encodable, not allowed by the
 * deserialization allow-list, or not known on the receiving side. The message names the class.
 */
public class TRADESerializationException extends TRADEException {
  private static final long serialVersionUID = 1L;

  public TRADESerializationException(String message) {
    super(message);
  }

  public TRADESerializationException(String message, Throwable cause) {
    super(message, cause);
  }
}
