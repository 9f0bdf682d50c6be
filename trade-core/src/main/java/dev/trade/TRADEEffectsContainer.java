package dev.trade;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Holds the {@link TRADEEffect}s of a service that carries more than one; the compiler writes it,
 * users write the repeated {@code @TRADEEffect} instead. Read the effects with
 * {@code method.getAnnotationsByType(TRADEEffect.class)}, or from a service info's
 * {@link TRADEServiceInfo#getAnnotations()}, where this container appears as it was declared.
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface TRADEEffectsContainer {
  /**
   * The effects, in declaration order.
   *
   * @return the effects
   */
  TRADEEffect[] value();
}
