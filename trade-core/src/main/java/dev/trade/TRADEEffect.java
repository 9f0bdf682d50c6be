package dev.trade;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Repeatable;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Describes an effect of a service: what holds after it is called ({@link #effect}), when
 * ({@link #type}), what can be observed to check it ({@link #observable}) and what else changes
 * ({@link #sideEffect}). Repeatable: a service may carry several.
 *
 * <p>Metadata only: TRADE does not interpret it. It travels with the service's description to
 * every container (see {@link TRADEServiceInfo#getAnnotations()}), so that planners anywhere in the
 * system can read it. The strings are the user's own notation (DIARC writes predicates such as
 * {@code "holding(?actor,?object)"}).
 *
 * <pre>{@code
 * @TRADEService
 * @TRADEEffect(effect = "open(gripper)", type = TRADEEffectType.SUCCESS)
 * @TRADEEffect(effect = "stopped(arm)", type = TRADEEffectType.FAILURE)
 * public boolean openGripper(int speed) { ... }
 * }</pre>
 */
@Documented
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
@Repeatable(TRADEEffectsContainer.class)
public @interface TRADEEffect {
  /**
   * The effects, in the user's notation.
   *
   * @return the effects
   */
  String[] effect();

  /**
   * When the effects hold.
   *
   * @return the kind of effect
   */
  TRADEEffectType type();

  /**
   * What can be observed to check the effects; none by default.
   *
   * @return the observables
   */
  String[] observable() default {};

  /**
   * Other changes the call causes; none by default.
   *
   * @return the side effects
   */
  String[] sideEffect() default {};
}
