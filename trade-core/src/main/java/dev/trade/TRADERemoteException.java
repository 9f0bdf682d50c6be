package dev.trade;

/**
 * Stands in for an exception thrown by a service in another container whose class is not known
 * (or not allowed) here. It carries the remote type name, message and stack trace; it is the cause
 * of the {@link TRADEInvocationException} the caller receives.
 */
public class TRADERemoteException extends TRADEException {
  private static final long serialVersionUID = 1L;

  private final String remoteTypeName;

  public TRADERemoteException(String remoteTypeName, String message, Throwable cause) {
    super(remoteTypeName + (message == null ? "" : ": " + message), cause);
    this.remoteTypeName = remoteTypeName;
  }

  /** The fully qualified class name of the exception the remote service threw. */
  public String getRemoteTypeName() {
    return remoteTypeName;
  }
}
