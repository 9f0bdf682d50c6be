package dev.trade.internal.registry;

import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import java.lang.annotation.Annotation;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.InaccessibleObjectException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Parameter;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Finds the services of a provider class and prepares them for invocation: reflection happens here,
 * once per registration, never per call. Stateless and thread-safe.
 *
 * <p>A public, non-static, non-bridge method is a service when it, or a method it overrides or
 * implements anywhere in the class hierarchy, carries {@link TRADEService}. An annotated method
 * that is not public, or is static, is a registration error.
 */
final class ServiceScanner {
  private static final MethodType INVOKER_TYPE =
      MethodType.methodType(Object.class, Object.class, Object[].class);

  private ServiceScanner() {}

  /** The service methods of {@code type}, in a stable order (by name, then parameter types). */
  static List<Method> serviceMethods(Class<?> type) throws TRADERegistrationException {
    List<Class<?>> hierarchy = hierarchy(type);
    for (Class<?> t : hierarchy) {
      for (Method m : t.getDeclaredMethods()) {
        if (!m.isAnnotationPresent(TRADEService.class)) {
          continue;
        }
        if (!Modifier.isPublic(m.getModifiers())) {
          throw error(m, "@TRADEService methods must be public; make it public or remove the annotation");
        }
        if (Modifier.isStatic(m.getModifiers())) {
          throw error(m, "@TRADEService methods must not be static; services belong to a registered"
              + " object, so make it an instance method");
        }
      }
    }
    Map<String, Method> bySignature = new LinkedHashMap<>();
    for (Method m : type.getMethods()) {
      if (m.isBridge() || m.isSynthetic() || Modifier.isStatic(m.getModifiers())) {
        continue;
      }
      if (!annotatedInHierarchy(hierarchy, m)) {
        continue;
      }
      String key = m.getName() + Arrays.toString(m.getParameterTypes());
      // Of several declarations of one signature (interfaces and an implementation), keep the
      // most specific: the one Java would dispatch to on this type.
      Method current = bySignature.get(key);
      if (current == null || current.getDeclaringClass().isAssignableFrom(m.getDeclaringClass())) {
        bySignature.put(key, m);
      }
    }
    List<Method> result = new ArrayList<>(bySignature.values());
    result.sort((a, b) -> {
      int c = a.getName().compareTo(b.getName());
      return c != 0 ? c : Arrays.toString(a.getParameterTypes())
          .compareTo(Arrays.toString(b.getParameterTypes()));
    });
    return result;
  }

  /** Builds the descriptor data and the invoker for one service method of {@code target}. */
  static LocalService prepare(Object target, Method m, DescriptorFactory factory)
      throws TRADERegistrationException {
    List<Class<?>> hierarchy = hierarchy(target.getClass());
    Parameter[] params = m.getParameters();
    Parameter[] named = namedParameters(hierarchy, m, params);
    List<String> names = new ArrayList<>(params.length);
    List<String> typeNames = new ArrayList<>(params.length);
    for (int i = 0; i < params.length; i++) {
      names.add(named[i].getName());
      typeNames.add(params[i].getType().getTypeName());
    }
    List<String> exceptions = new ArrayList<>();
    for (Class<?> x : m.getExceptionTypes()) {
      exceptions.add(x.getName());
    }
    ServiceDescriptor d = factory.create(m.getName(), names, typeNames,
        m.getReturnType().getTypeName(), annotations(hierarchy, m),
        m.getGenericReturnType().getTypeName(), exceptions, parameterAnnotations(hierarchy, m));
    return new LocalService(d, target, m, invoker(hierarchy, m));
  }

  /** The invoker of one service method of {@code type} (see {@link LocalService#invoker()}). */
  static MethodHandle prepareInvoker(Class<?> type, Method m) throws TRADERegistrationException {
    return invoker(hierarchy(type), m);
  }

  /** Supplies container identity and a fresh service id for each prepared service. */
  interface DescriptorFactory {
    ServiceDescriptor create(String name, List<String> parameterNames, List<String> parameterTypeNames,
        String returnTypeName, List<Annotation> annotations, String genericReturnTypeName,
        List<String> exceptionTypeNames, List<List<Annotation>> parameterAnnotations);
  }

  private static MethodHandle invoker(List<Class<?>> hierarchy, Method m)
      throws TRADERegistrationException {
    MethodHandle raw = null;
    // Prefer a declaration the public lookup may call (a public interface or class): then the
    // provider class itself may be package-private or anonymous without any setAccessible.
    for (Class<?> t : hierarchy) {
      Method decl = declared(t, m);
      if (decl != null && Modifier.isPublic(t.getModifiers())
          && t.getModule().isExported(t.getPackageName())) {
        try {
          raw = MethodHandles.publicLookup().unreflect(decl);
          break;
        } catch (IllegalAccessException ignored) {
          // Not reachable from outside (e.g. a nested class in a non-public class): try the next.
        }
      }
    }
    if (raw == null) {
      try {
        m.setAccessible(true);
        raw = MethodHandles.lookup().unreflect(m);
      } catch (InaccessibleObjectException | IllegalAccessException e) {
        throw error(m, "TRADE cannot call it: " + e.getMessage() + "; open package "
            + m.getDeclaringClass().getPackageName() + " to module dev.trade, or make the class public");
      }
    }
    return raw.asSpreader(Object[].class, m.getParameterCount()).asType(INVOKER_TYPE);
  }

  private static boolean annotatedInHierarchy(List<Class<?>> hierarchy, Method m) {
    for (Class<?> t : hierarchy) {
      Method decl = declared(t, m);
      if (decl != null && decl.isAnnotationPresent(TRADEService.class)) {
        return true;
      }
    }
    return false;
  }

  private static Parameter[] namedParameters(List<Class<?>> hierarchy, Method m, Parameter[] own) {
    if (own.length == 0 || own[0].isNamePresent()) {
      return own;
    }
    for (Class<?> t : hierarchy) {
      Method decl = declared(t, m);
      if (decl != null && decl.getParameterCount() > 0 && decl.getParameters()[0].isNamePresent()) {
        return decl.getParameters();
      }
    }
    return own;
  }

  /** The method's own annotations, then those of the declarations it overrides, one per type. */
  private static List<Annotation> annotations(List<Class<?>> hierarchy, Method m) {
    Map<Class<? extends Annotation>, Annotation> byType = new LinkedHashMap<>();
    for (Annotation a : m.getAnnotations()) {
      byType.putIfAbsent(a.annotationType(), a);
    }
    for (Class<?> t : hierarchy) {
      Method decl = declared(t, m);
      if (decl != null) {
        for (Annotation a : decl.getAnnotations()) {
          byType.putIfAbsent(a.annotationType(), a);
        }
      }
    }
    return new ArrayList<>(byType.values());
  }

  /**
   * Per parameter: its own annotations, then those of the same parameter in the declarations the
   * method overrides, one per type (as for the method's own annotations).
   */
  private static List<List<Annotation>> parameterAnnotations(List<Class<?>> hierarchy, Method m) {
    List<Map<Class<? extends Annotation>, Annotation>> byType = new ArrayList<>();
    for (Annotation[] own : m.getParameterAnnotations()) {
      Map<Class<? extends Annotation>, Annotation> map = new LinkedHashMap<>();
      for (Annotation a : own) {
        map.putIfAbsent(a.annotationType(), a);
      }
      byType.add(map);
    }
    for (Class<?> t : hierarchy) {
      Method decl = declared(t, m);
      if (decl != null) {
        Annotation[][] inherited = decl.getParameterAnnotations();
        for (int i = 0; i < inherited.length && i < byType.size(); i++) {
          for (Annotation a : inherited[i]) {
            byType.get(i).putIfAbsent(a.annotationType(), a);
          }
        }
      }
    }
    List<List<Annotation>> result = new ArrayList<>(byType.size());
    for (Map<Class<? extends Annotation>, Annotation> map : byType) {
      result.add(new ArrayList<>(map.values()));
    }
    return result;
  }

  private static Method declared(Class<?> t, Method m) {
    try {
      return t.getDeclaredMethod(m.getName(), m.getParameterTypes());
    } catch (NoSuchMethodException e) {
      return null;
    }
  }

  /** The type, its superclasses, then all its interfaces breadth-first, each once. */
  static List<Class<?>> hierarchy(Class<?> type) {
    Set<Class<?>> seen = new LinkedHashSet<>();
    for (Class<?> c = type; c != null && c != Object.class; c = c.getSuperclass()) {
      seen.add(c);
    }
    Deque<Class<?>> queue = new ArrayDeque<>(seen);
    while (!queue.isEmpty()) {
      for (Class<?> i : queue.poll().getInterfaces()) {
        if (seen.add(i)) {
          queue.add(i);
        }
      }
    }
    return new ArrayList<>(seen);
  }

  private static TRADERegistrationException error(Method m, String problem) {
    return new TRADERegistrationException(problem + "\n    for method "
        + m.getDeclaringClass().getName() + "." + m.getName()
        + "(" + String.join(", ", Arrays.stream(m.getParameterTypes()).map(Class::getTypeName)
            .toArray(String[]::new)) + ")");
  }
}
