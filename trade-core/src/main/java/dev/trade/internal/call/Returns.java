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
    Class<?> want = Types.box(requested);
    Class<?> have = Types.box(declared);
    // Narrowing (declared Object, requested String) is allowed and checked on the value.
    if (declared == void.class || !want.isAssignableFrom(have) && !have.isAssignableFrom(want)) {
      throw mismatch(d, requested, declared);
    }
  }

  // The messages are built out of line: every call runs check() and convert(), and the smaller
  // they are, the more of the call the JIT compiles into one piece.
  private static TRADEBadArgumentsException mismatch(ServiceDescriptor d, Class<?> requested,
      Class<?> declared) {
    if (declared == void.class) {
      return new TRADEBadArgumentsException("Service " + d.signature() + " returns void; call it"
          + " with void.class or Object.class, not " + requested.getTypeName());
    }
    return new TRADEBadArgumentsException("Service " + d.signature() + " returns "
        + declared.getTypeName() + ", which is not a " + requested.getTypeName());
  }

  private static TRADEBadArgumentsException wrongValue(ServiceDescriptor d, Class<?> requested,
      Object value) {
    return new TRADEBadArgumentsException("Service " + d.signature() + " returned "
        + (value == null ? "null" : "a " + value.getClass().getTypeName()) + ", which is not a "
        + requested.getTypeName());
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
        throw wrongValue(d, requested, null);
      }
      return null;
    }
    if (!Types.box(requested).isInstance(value)) {
      throw wrongValue(d, requested, value);
    }
    return (T) value;
  }
}
