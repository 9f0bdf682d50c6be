package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Types;
import java.util.List;

/**
 * Which parameters a callback service takes, and so what a delivery hands it: checked once, when
 * the notification is requested, against what its type delivers.
 */
enum Shape {
  /** {@code ()}: told that it happened. */
  NONE,
  /** {@code (R result)}, or {@code (TRADEServiceInfo)} for joined and left. */
  VALUE,
  /** {@code (R result, Throwable failure)}: exactly one of them is non-null. */
  VALUE_OR_FAILURE;

  private static final String INFO = TRADEServiceInfo.class.getName();

  /**
   * The shape of {@code callback} for {@code kind}, where {@code service} is the service whose
   * result is delivered (null when none).
   *
   * @throws TRADEBadArgumentsException naming the callback and the parameter lists it may have
   */
  static Shape of(Kind kind, ServiceDescriptor service, ServiceDescriptor callback)
      throws TRADEBadArgumentsException {
    List<String> params = callback.parameterTypeNames();
    String expected;
    if (kind == Kind.JOINED || kind == Kind.LEFT) {
      if (params.size() == 1 && accepts(params.get(0), INFO)) {
        return VALUE;
      }
      expected = "(" + INFO + ")";
    } else if (service == null || kind.isCondition()) {
      if (params.isEmpty()) {
        return NONE;
      }
      expected = "()";
    } else {
      String result = service.returnTypeName();
      if (params.isEmpty()) {
        return NONE;
      }
      if (accepts(params.get(0), result)) {
        if (params.size() == 1) {
          return VALUE;
        }
        if (params.size() == 2 && accepts(params.get(1), TRADEException.class.getName())) {
          return VALUE_OR_FAILURE;
        }
      }
      String r = "void".equals(result) ? "Object" : result;
      expected = "(), (" + r + ") or (" + r + ", Throwable) for the result of "
          + service.signature();
    }
    throw new TRADEBadArgumentsException("Callback " + callback.signature() + " of container "
        + callback.containerName() + " cannot take what '" + kind.label() + "' delivers: it must"
        + " take " + expected);
  }

  /**
   * Whether a parameter declared as {@code declared} takes a value of type {@code given} (a void
   * result is null, which every reference parameter takes). Types unknown in this JVM compare by
   * name.
   */
  static boolean accepts(String declared, String given) {
    ClassLoader loader = Shape.class.getClassLoader();
    Class<?> d = resolve(declared, loader);
    if ("void".equals(given)) {
      return d == null || !d.isPrimitive();
    }
    Class<?> g = resolve(given, loader);
    if (d == null || g == null) {
      return declared.equals(given) || d == Object.class;
    }
    return Types.accepts(d, g);
  }

  private static Class<?> resolve(String name, ClassLoader fallback) {
    ClassLoader context = Thread.currentThread().getContextClassLoader();
    Class<?> c = context == null ? null : Types.resolve(name, context);
    return c != null ? c : Types.resolve(name, fallback);
  }
}
