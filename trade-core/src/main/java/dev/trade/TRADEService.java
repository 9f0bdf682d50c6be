package dev.trade;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Marks a public method as a TRADE service.
 *
 * <p>When an object is registered, every public method that carries this annotation, or that
 * overrides or implements a method carrying it in any superclass or interface, becomes a service
 * usable from every container of the system. Placing it on interface methods only, and leaving the
 * implementing class free of it, is the usual style.
 *
 * <p>Registration rejects annotated methods that are not public or are static, with a message that
 * names the method; synthetic and bridge methods are never services.
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface TRADEService {}
