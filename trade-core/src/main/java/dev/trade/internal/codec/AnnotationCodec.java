package dev.trade.internal.codec;

import dev.trade.TRADESerializationException;
import java.lang.annotation.Annotation;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Encodes annotation instances as their type name and member values, and re-creates them on decoding
 * as {@link Proxy} instances that follow the {@link Annotation} contract ({@link AnnotationHandler}).
 * Member values are primitives, strings, classes, enums, annotations and arrays of those, so the
 * general value encoding covers them.
 */
final class AnnotationCodec {

  private static final ClassValue<Members> MEMBERS =
      new ClassValue<>() {
        @Override
        protected Members computeValue(Class<?> type) {
          return new Members(type);
        }
      };

  /** Annotation members are never collections: no value needs adapting to a declared class. */
  private static final AllowList NO_ADAPTATION = AllowList.of("!*");

  private AnnotationCodec() {}

  static Members members(Class<?> annotationType) {
    return MEMBERS.get(annotationType);
  }

  static void write(Encoder e, Annotation a) throws TRADESerializationException {
    Class<? extends Annotation> type = a.annotationType();
    Members m = members(type);
    if (m.problem != null) {
      throw new TRADESerializationException(
          "Cannot encode annotation @" + type.getName() + ": " + m.problem);
    }
    e.enter(a);
    ByteSink out = e.out;
    out.writeByte(Tags.ANNOTATION);
    out.writeText(type.getName());
    out.writeVarUInt(m.names.length);
    for (int i = 0; i < m.names.length; i++) {
      out.writeText(m.names[i]);
      e.writeValue(m.get(i, a));
    }
    e.leave();
  }

  static Annotation read(Decoder d) throws TRADESerializationException {
    String typeName = d.readName();
    Class<?> type = d.resolveAnnotationType(typeName);
    if (!type.isAnnotation()) {
      throw new TRADESerializationException(
          "Cannot decode annotation @" + typeName + ": it is not an annotation type here");
    }
    int n = d.readCount(2);
    Members m = members(type);
    d.enter();
    Map<String, Object> given = new HashMap<>();
    AllowList outer = d.allowList;
    try {
      for (int i = 0; i < n; i++) {
        String name = d.readName();
        // The enum and annotation types a member declares may arrive in it, as the annotation
        // type itself may (see Decoder.resolveAnnotationType).
        int at = m.problem == null ? m.indexOf(name) : -1;
        d.allowList = at < 0 ? outer : outer.with(m.declared[at]);
        given.put(name, d.readValue());
      }
    } finally {
      d.allowList = outer;
    }
    d.leave();
    if (m.problem != null) {
      throw new TRADESerializationException(
          "Cannot decode annotation @" + typeName + ": " + m.problem);
    }
    Object[] values = new Object[m.names.length];
    for (int i = 0; i < values.length; i++) {
      Object v = given.containsKey(m.names[i]) ? given.get(m.names[i]) : m.defaults[i];
      if (v == null) {
        throw new TRADESerializationException(
            "Cannot decode annotation @" + typeName + ": member " + m.names[i] + " is missing");
      }
      values[i] = Structs.fit(v, m.types[i], NO_ADAPTATION, "member ", m.names[i], "@" + typeName);
    }
    try {
      return (Annotation) Proxy.newProxyInstance(
          type.getClassLoader(), new Class<?>[] {type}, new AnnotationHandler(m, values));
    } catch (IllegalArgumentException | SecurityException e) {
      throw new TRADESerializationException(
          "Cannot re-create annotation @" + typeName + ": " + e.getMessage(), e);
    }
  }

  /** The members of one annotation type, sorted by name; immutable. */
  static final class Members {
    final Class<?> type;
    final String[] names;
    final Class<?>[] types;
    final Object[] defaults;
    /** Per member: the enum or annotation type its values are of, as a set of one name, or empty. */
    final Set<String>[] declared;
    /** {@code (Object)Object} getters for the members of any instance of the type. */
    private final MethodHandle[] getters;
    /** Why members cannot be read (the type is not accessible), or null. */
    final String problem;

    private Members(Class<?> type) {
      this.type = type;
      Method[] methods;
      String trouble = type.isAnnotation() ? null : "it is not an annotation type";
      try {
        // A loop, not a stream: the first service table a container sends encodes an annotation,
        // and a sorted stream would load some 30 classes for it.
        List<Method> members = new ArrayList<>();
        for (Method m : type.getDeclaredMethods()) {
          if (!Modifier.isStatic(m.getModifiers()) && m.getParameterCount() == 0
              && !m.isSynthetic()) {
            members.add(m);
          }
        }
        members.sort(Comparator.comparing(Method::getName));
        methods = members.toArray(new Method[0]);
      } catch (RuntimeException | LinkageError e) { // a member type is missing here
        methods = new Method[0];
        trouble = "its members cannot be read (" + e + ")";
      }
      int n = methods.length;
      names = new String[n];
      types = new Class<?>[n];
      defaults = new Object[n];
      @SuppressWarnings("unchecked")
      Set<String>[] declaredTypes = new Set[n];
      declared = declaredTypes;
      getters = new MethodHandle[n];
      for (int i = 0; i < n && trouble == null; i++) {
        Method method = methods[i];
        names[i] = method.getName();
        types[i] = method.getReturnType();
        Class<?> element = types[i].isArray() ? types[i].getComponentType() : types[i];
        declared[i] = element.isEnum() || element.isAnnotation() ? Set.of(element.getName()) : Set.of();
        try {
          defaults[i] = method.getDefaultValue();
          method.setAccessible(true);
          getters[i] = MethodHandles.lookup().unreflect(method)
              .asType(MethodType.methodType(Object.class, Object.class));
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
          trouble = "member " + method.getName() + " cannot be read (" + e + ")";
        }
      }
      problem = trouble;
    }

    int indexOf(String name) {
      for (int i = 0; i < names.length; i++) {
        if (names[i].equals(name)) {
          return i;
        }
      }
      return -1;
    }

    /** Member {@code i} of {@code annotation}, an instance of {@link #type}. */
    Object get(int i, Object annotation) throws TRADESerializationException {
      try {
        return (Object) getters[i].invokeExact(annotation);
      } catch (Error e) {
        throw e;
      } catch (Throwable e) {
        throw new TRADESerializationException(
            "Cannot read member " + names[i] + " of @" + type.getName() + ": " + e, e);
      }
    }
  }
}
