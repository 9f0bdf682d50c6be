package org.example.jvm.diarc.action;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** Like DIARC's {@code @Action}: marks services an action database collects. */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.METHOD)
public @interface Action {
  /** The kind of action, an enum member as DIARC's annotations have. */
  Kind kind() default Kind.PRIMITIVE;

  /** Kinds of actions. */
  enum Kind { PRIMITIVE, SCRIPT }
}
