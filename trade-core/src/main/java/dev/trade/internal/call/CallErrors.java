package dev.trade.internal.call;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADELockedException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.TRADETimeoutException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.concurrent.TimeUnit;

/**
 * Every text a failed call reports, in one place, so that the same failure reads the same
 * whichever way the call went (local, remote, forwarded). Callers match the starts of these texts
 * ("Service not available any longer", "Service not available now"), so they do not change.
 * Stateless.
 */
public final class CallErrors {
  private static final String GONE = "Service not available any longer: ";
  private static final String NOT_NOW = "Service not available now: ";

  private CallErrors() {}

  /** A service that is gone: deregistered, or its container left or cannot be reached. */
  public static TRADEServiceUnavailableException gone(ServiceDescriptor d, String why) {
    return new TRADEServiceUnavailableException(goneText(d, why));
  }

  /** The text of {@link #gone(ServiceDescriptor, String)}. */
  public static String goneText(ServiceDescriptor d, String why) {
    return GONE + d.signature() + " of container " + d.containerName() + " (" + why + ")";
  }

  /** A service gone, where only the reason is known (a container answering for a route). */
  public static String goneText(String why) {
    return GONE + why;
  }

  /** A service that cannot take the call now, though it may later. */
  public static String notNowText(String why) {
    return NOT_NOW + why;
  }

  /**
   * A call refused by the service's lock: {@code why} says which lock is in the way, or why the
   * call's own lock does not hold the service.
   */
  public static TRADELockedException locked(ServiceDescriptor d, String why) {
    return new TRADELockedException("Service " + d.signature() + " of container "
        + d.containerName() + " refused the call: " + why);
  }

  /** The caller waited {@code timeoutNanos} without an answer; {@code more} may say why. */
  public static TRADETimeoutException timedOut(ServiceDescriptor d, long timeoutNanos, String more) {
    return new TRADETimeoutException("Service " + d.signature() + " of container "
        + d.containerName() + " did not answer within "
        + TimeUnit.NANOSECONDS.toMillis(timeoutNanos) + " ms" + more);
  }

  /** The service itself threw {@code t}. */
  public static TRADEInvocationException threw(ServiceDescriptor d, Throwable t) {
    return new TRADEInvocationException("Service " + d.signature() + " threw "
        + t.getClass().getName() + (t.getMessage() == null ? "" : ": " + t.getMessage()), t);
  }

  /**
   * The providing container's access control refused the call: {@code missing} says what the
   * caller lacked (a role, a valid or fresh proof), never a secret.
   */
  public static TRADENotAuthorizedException notAuthorized(ServiceDescriptor d, String missing) {
    return new TRADENotAuthorizedException("Not authorized: " + d.signature() + " of container "
        + d.containerName() + " needs " + missing);
  }

  /** A number of arguments that does not match the service's parameters. */
  public static TRADEBadArgumentsException argumentCount(ServiceDescriptor d, int given) {
    int expected = d.parameterTypeNames().size();
    return new TRADEBadArgumentsException("Service " + d.signature() + " takes " + expected
        + " argument" + (expected == 1 ? "" : "s") + " " + parameterList(d) + " but got " + given);
  }

  /** Argument {@code i} does not fit its parameter: {@code problem} says how. */
  public static TRADEBadArgumentsException badArgument(ServiceDescriptor d, int i, String problem) {
    return new TRADEBadArgumentsException("Argument " + i + " ('" + d.parameterNames().get(i)
        + "', expected " + d.parameterTypeNames().get(i) + ") " + problem
        + "\n    for service " + d.signature());
  }

  private static String parameterList(ServiceDescriptor d) {
    StringBuilder sb = new StringBuilder("(");
    for (int i = 0; i < d.parameterNames().size(); i++) {
      sb.append(i == 0 ? "" : ", ").append(d.parameterTypeNames().get(i)).append(' ')
          .append(d.parameterNames().get(i));
    }
    return sb.append(')').toString();
  }
}
