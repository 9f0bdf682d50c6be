package dev.trade;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Which roles may call a service: put it next to {@link TRADEService} on the service method, or on
 * the provider's class for all of its services (the method's wins). A caller may call the service
 * when its principal has at least one of the roles; {@link #ANYONE} lets every caller through,
 * anonymous ones included.
 *
 * <p>Without it, a service is open to anyone, except those in the reserved group
 * {@code trade.system}, which require the role {@code admin}. The access file
 * ({@code PRINCIPALSFILE}) can override it per service name or group (docs/security.md). The
 * providing container enforces it, first in its call chain, so a refused call never runs.
 *
 * <pre>{@code
 * @TRADEService
 * @TRADEAccess({"operator", "admin"})
 * public void moveArm(double[] pose) { ... }
 * }</pre>
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.METHOD, ElementType.TYPE})
public @interface TRADEAccess {
  /** The role that stands for every caller, anonymous ones included. */
  String ANYONE = "*";

  /**
   * The roles, any one of which lets a caller call the service; {@link #ANYONE} for every caller.
   * An empty array lets no caller through.
   *
   * @return the roles
   */
  String[] value();
}
