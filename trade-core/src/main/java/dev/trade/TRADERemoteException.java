package dev.trade;

/**
 * Stands in for an exception thrown by a service in another container whose class is not known
 * (or not allowed) here. It carries the remote type name, message and stack trace; it is the cause
 * of the {@link TRADEInvocationException} the caller receives.
 *
 * <p>Its message says how to receive the real class instead: have it on the caller's class path
 * and add it, or its package, to the caller's {@code SERIALIZATIONALLOWLIST} setting
 * (docs/configuration.md).
 */
public class TRADERemoteException extends TRADEException {
  private static final long serialVersionUID = 1L;

  /** The remote exception's class name. */
  private final String remoteTypeName;
  /** The remote exception's message, or null. */
  private final String remoteMessage;

  /**
   * A stand-in for an exception of class {@code remoteTypeName}.
   *
   * @param remoteTypeName the fully qualified name of the remote exception's class
   * @param message the remote exception's message, or null
   * @param cause the remote exception's cause, as decoded here, or null
   */
  public TRADERemoteException(String remoteTypeName, String message, Throwable cause) {
    super(remoteTypeName + (message == null ? "" : ": " + message) + hint(remoteTypeName), cause);
    this.remoteTypeName = remoteTypeName;
    this.remoteMessage = message;
  }

  private static String hint(String typeName) {
    int dot = typeName.lastIndexOf('.');
    String pkg = dot < 0 ? "" : " (or " + typeName.substring(0, dot) + ".*)";
    return " [not received as itself: to receive it, have " + typeName + " on this JVM's class path"
        + " and add it" + pkg + " to the SERIALIZATIONALLOWLIST setting]";
  }

  /**
   * The class of the exception the remote service threw.
   *
   * @return its fully qualified class name
   */
  public String getRemoteTypeName() {
    return remoteTypeName;
  }

  /**
   * The message of the exception the remote service threw.
   *
   * @return that message, or null when it had none
   */
  public String getRemoteMessage() {
    return remoteMessage;
  }
}
