package dev.trade.internal.call;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Types;
import java.util.List;

/**
 * Checks call arguments against a service's signature before anything runs, and applies the
 * primitive widening conversions that Java reflection applies ({@code int} → {@code long} …).
 * Stateless and thread-safe.
 */
public final class Arguments {
  private static final Object[] NONE = {};

  private Arguments() {}

  /**
   * Undoes Java's varargs spreading for services with a single array parameter: in
   * {@code info.call(void.class, new String[] {"a", "b"})} Java passes the array itself as the
   * argument list, although the caller meant one argument. A null list means no arguments.
   */
  public static Object[] normalize(ServiceDescriptor d, Object[] args) {
    if (args == null) {
      return NONE;
    }
    List<String> types = d.parameterTypeNames();
    if (types.size() == 1 && types.get(0).endsWith("[]")
        && !(args.length == 1 && (args[0] == null || args[0].getClass().isArray()))) {
      return new Object[] {args};
    }
    return args;
  }

  /**
   * Returns {@code args}, or a converted copy where a value needed widening.
   *
   * @throws TRADEBadArgumentsException naming the first parameter (index, name, expected type)
   *     that the arguments do not fit, or the expected parameter list on a count mismatch
   */
  public static Object[] check(ServiceDescriptor d, List<Class<?>> types, Object[] args)
      throws TRADEBadArgumentsException {
    if (args.length != types.size()) {
      throw CallErrors.argumentCount(d, args.length);
    }
    Object[] result = args;
    for (int i = 0; i < args.length; i++) {
      Class<?> type = types.get(i);
      Object v = args[i];
      if (v == null) {
        if (type.isPrimitive()) {
          throw bad(d, i, "is null, but the parameter is primitive");
        }
        continue;
      }
      if (Types.box(type).isInstance(v)) {
        continue;
      }
      Object widened = type.isPrimitive() ? widen(type, v) : null;
      if (widened == null) {
        throw notA(d, i, v);
      }
      if (result == args) {
        result = args.clone();
      }
      result[i] = widened;
    }
    return result;
  }

  // Out of line, as are the other messages: check() runs on every call, and the smaller it is, the
  // more of the call the JIT compiles into one piece.
  private static TRADEBadArgumentsException notA(ServiceDescriptor d, int index, Object v) {
    return bad(d, index, "is a " + v.getClass().getTypeName());
  }

  private static Object widen(Class<?> to, Object v) {
    long integral;
    if (v instanceof Byte || v instanceof Short || v instanceof Integer) {
      integral = ((Number) v).longValue();
    } else if (v instanceof Character) {
      integral = (Character) v;
      if (to == short.class) {
        return null;
      }
    } else if (v instanceof Long) {
      integral = (Long) v;
      if (to == float.class) {
        return (float) integral;
      } else if (to == double.class) {
        return (double) integral;
      }
      return null;
    } else if (v instanceof Float && to == double.class) {
      return ((Float) v).doubleValue();
    } else {
      return null;
    }
    int rank = rank(v);
    if (to == short.class && rank < 2) {
      return (short) integral;
    } else if (to == int.class && rank < 3) {
      return (int) integral;
    } else if (to == long.class) {
      return integral;
    } else if (to == float.class) {
      return (float) integral;
    } else if (to == double.class) {
      return (double) integral;
    }
    return null;
  }

  /**
   * byte 1, short and char 2, int 3: a value widens to an integral type of a higher rank (char to
   * short is refused above, as Java refuses it).
   */
  private static int rank(Object v) {
    return v instanceof Byte ? 1 : v instanceof Short || v instanceof Character ? 2 : 3;
  }

  private static TRADEBadArgumentsException bad(ServiceDescriptor d, int i, String problem) {
    return CallErrors.badArgument(d, i, problem);
  }
}
