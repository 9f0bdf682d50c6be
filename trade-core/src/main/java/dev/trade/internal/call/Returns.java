package dev.trade.internal.call;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Types;

/**
 * The return side of {@code TRADEServiceInfo.call(Class<T>, ...)}: {@code void.class} gives null,
 * {@code Object.class} anything, a primitive class its boxed value. Stateless and thread-safe.
 */
public final class Returns {
  private Returns() {}

  /**
   * Fails before invoking when the requested return type cannot fit the declared one.
   *
   * @param declared the declared return type, or null when it is not known here (then only the
   *     value is checked after the call)
   */
  public static void check(ServiceDescriptor d, Class<?> requested, Class<?> declared)
      throws TRADEBadArgumentsException {
    if (requested == void.class || requested == Void.class || requested == Object.class
        || declared == null) {
      return;
    }
    if (declared == void.class) {
      throw new TRADEBadArgumentsException("Service " + d.signature() + " returns void; call it with"
          + " void.class or Object.class, not " + requested.getTypeName());
    }
    Class<?> want = Types.box(requested);
    Class<?> have = Types.box(declared);
    // Narrowing (declared Object, requested String) is allowed and checked on the value.
    if (!want.isAssignableFrom(have) && !have.isAssignableFrom(want)) {
      throw new TRADEBadArgumentsException("Service " + d.signature() + " returns "
          + declared.getTypeName() + ", which is not a " + requested.getTypeName());
    }
  }

  /** The value as the requested type, or a bad-arguments error naming both types. */
  @SuppressWarnings("unchecked")
  public static <T> T convert(ServiceDescriptor d, Class<T> requested, Object value)
      throws TRADEBadArgumentsException {
    if (requested == void.class || requested == Void.class) {
      return null;
    }
    if (value == null) {
      if (requested.isPrimitive()) {
        throw new TRADEBadArgumentsException("Service " + d.signature()
            + " returned null, which is not a " + requested.getTypeName());
      }
      return null;
    }
    Class<?> want = Types.box(requested);
    if (!want.isInstance(value)) {
      throw new TRADEBadArgumentsException("Service " + d.signature() + " returned a "
          + value.getClass().getTypeName() + ", which is not a " + requested.getTypeName());
    }
    return (T) value;
  }
}
