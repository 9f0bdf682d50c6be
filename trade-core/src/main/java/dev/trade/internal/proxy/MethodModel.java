package dev.trade.internal.proxy;

import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.UncheckedTRADEException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.Future;

/**
 * What one interface method means as a service call, parsed once: the service's name and
 * parameter types, the class to call with, whether it runs asynchronously and how its failures
 * are thrown. Immutable.
 */
final class MethodModel {
  final Method method;
  final String name;
  final Class<?>[] parameterTypes;
  /** The return type given to {@code TRADEServiceInfo.call}: for futures, their value's type. */
  final Class<?> callType;
  final boolean async;
  private final boolean throwsTradeException;
  private final List<Class<?>> declaredExceptions;

  private MethodModel(Method method, Class<?> callType, boolean async) {
    this.method = method;
    this.name = method.getName();
    this.parameterTypes = method.getParameterTypes();
    this.callType = callType;
    this.async = async;
    boolean declares = false;
    for (Class<?> e : method.getExceptionTypes()) {
      declares |= e.isAssignableFrom(TRADEException.class);
    }
    this.throwsTradeException = declares;
    this.declaredExceptions = List.of(method.getExceptionTypes());
  }

  /**
   * The models of every abstract method of {@code type}, checked now so that a bad interface
   * fails when the proxy is made rather than on a call.
   *
   * @throws IllegalArgumentException naming the interface or the method and how to fix it
   */
  static Map<Method, MethodModel> parse(Class<?> type) {
    if (!type.isInterface()) {
      throw new IllegalArgumentException(type.getName() + " is not an interface; a proxy"
          + " implements an interface: declare the services' methods in one and pass it");
    }
    if (type.isAnnotation()) {
      throw new IllegalArgumentException(type.getName() + " is an annotation type; pass an"
          + " interface that declares the services' methods");
    }
    Map<Method, MethodModel> models = new LinkedHashMap<>();
    for (Method m : type.getMethods()) {
      if (!Modifier.isStatic(m.getModifiers()) && !m.isDefault()) {
        models.put(m, of(m));
      }
    }
    return Map.copyOf(models);
  }

  private static MethodModel of(Method m) {
    if (m.getTypeParameters().length > 0) {
      throw methodError(m, "is generic; a service has concrete parameter types, so declare them"
          + " (a proxy finds the service by them)");
    }
    Type[] generic = m.getGenericParameterTypes();
    for (int i = 0; i < generic.length; i++) {
      if (generic[i] instanceof TypeVariable) {
        throw methodError(m, "parameter " + i + " has the type variable " + generic[i]
            + "; declare a concrete type (a proxy finds the service by its parameter types)");
      }
    }
    Class<?> raw = m.getReturnType();
    if (raw == CompletableFuture.class || raw == CompletionStage.class) {
      return new MethodModel(m, valueType(m), true);
    }
    if (Future.class.isAssignableFrom(raw)) {
      throw methodError(m, "returns " + raw.getSimpleName() + "; return CompletableFuture<T> to"
          + " call asynchronously, or T to call and wait");
    }
    return new MethodModel(m, raw, false);
  }

  private static Class<?> valueType(Method m) {
    Type t = m.getGenericReturnType();
    if (t instanceof ParameterizedType) {
      Type arg = ((ParameterizedType) t).getActualTypeArguments()[0];
      if (arg instanceof Class) {
        return (Class<?>) arg;
      }
      if (arg instanceof ParameterizedType) {
        return (Class<?>) ((ParameterizedType) arg).getRawType();
      }
    }
    throw methodError(m, "returns " + t.getTypeName() + " without a concrete value type;"
        + " declare it, e.g. " + m.getReturnType().getSimpleName() + "<Boolean> or "
        + m.getReturnType().getSimpleName() + "<Void>");
  }

  /**
   * What the method throws for {@code e}: the service's own exception when the method declares
   * its type, else {@code e} itself when the method declares {@code TRADEException}, else an
   * {@link UncheckedTRADEException} around it.
   */
  Throwable failure(TRADEException e) {
    if (e instanceof TRADEInvocationException) {
      Throwable cause = e.getCause();
      if (cause != null && !(cause instanceof TRADEException)) {
        for (Class<?> declared : declaredExceptions) {
          if (declared.isInstance(cause) && declared != Exception.class
              && declared != Throwable.class) {
            return cause;
          }
        }
      }
    }
    return throwsTradeException ? e : new UncheckedTRADEException(e);
  }

  /** {@code Interface.method(T1,T2)}, for messages. */
  String describe() {
    return describe(method);
  }

  static String describe(Method m) {
    StringBuilder sb = new StringBuilder(m.getDeclaringClass().getSimpleName()).append('.')
        .append(m.getName()).append('(');
    Class<?>[] types = m.getParameterTypes();
    for (int i = 0; i < types.length; i++) {
      sb.append(i == 0 ? "" : ",").append(types[i].getTypeName());
    }
    return sb.append(')').toString();
  }

  private static IllegalArgumentException methodError(Method m, String problem) {
    return new IllegalArgumentException("Method " + problem + "\n    for method "
        + m.getDeclaringClass().getName() + "." + m.getName());
  }
}
