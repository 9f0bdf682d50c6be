package dev.trade.internal.codec;

import java.io.Externalizable;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.lang.annotation.Annotation;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Proxy;
import java.lang.reflect.RecordComponent;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;

/**
 * How values of one class are encoded, and for records and data classes the cached accessors that
 * read and rebuild them, so that reflection runs once per class and never per value.
 *
 * <p>Models are computed on first use of a class and cached for the class's lifetime; they are
 * immutable and safe for concurrent use.
 */
final class ClassModel {

  /** The encoding chosen for a class, in the order {@link #build} tries them. */
  enum Kind {
    STRING, BOOLEAN, BYTE, SHORT, INT, LONG, FLOAT, DOUBLE, CHAR,
    BYTES, BOOLEANS, SHORTS, CHARS, INTS, LONGS, FLOATS, DOUBLES, ARRAY,
    BIG_INTEGER, BIG_DECIMAL, UUID, INSTANT, DURATION, CLASS,
    ENUM, THROWABLE, ANNOTATION,
    LIST, SET, MAP, COLLECTION,
    RECORD, DATA, SERIALIZABLE, UNSUPPORTED
  }

  private static final Map<Class<?>, Kind> EXACT =
      Map.ofEntries(
          Map.entry(String.class, Kind.STRING),
          Map.entry(Boolean.class, Kind.BOOLEAN),
          Map.entry(Byte.class, Kind.BYTE),
          Map.entry(Short.class, Kind.SHORT),
          Map.entry(Integer.class, Kind.INT),
          Map.entry(Long.class, Kind.LONG),
          Map.entry(Float.class, Kind.FLOAT),
          Map.entry(Double.class, Kind.DOUBLE),
          Map.entry(Character.class, Kind.CHAR),
          Map.entry(byte[].class, Kind.BYTES),
          Map.entry(boolean[].class, Kind.BOOLEANS),
          Map.entry(short[].class, Kind.SHORTS),
          Map.entry(char[].class, Kind.CHARS),
          Map.entry(int[].class, Kind.INTS),
          Map.entry(long[].class, Kind.LONGS),
          Map.entry(float[].class, Kind.FLOATS),
          Map.entry(double[].class, Kind.DOUBLES),
          Map.entry(BigInteger.class, Kind.BIG_INTEGER),
          Map.entry(BigDecimal.class, Kind.BIG_DECIMAL),
          Map.entry(UUID.class, Kind.UUID),
          Map.entry(Instant.class, Kind.INSTANT),
          Map.entry(Duration.class, Kind.DURATION),
          Map.entry(Class.class, Kind.CLASS));

  private static final ClassValue<ClassModel> MODELS =
      new ClassValue<>() {
        @Override
        protected ClassModel computeValue(Class<?> type) {
          return build(type);
        }
      };

  final Class<?> type;
  final Kind kind;
  /** Why a class is not a codable record or data class, for error messages; else null. */
  final String reason;
  /** RECORD and DATA: component or field names, types and {@code (Object)Object} getters. */
  final String[] names;
  final Class<?>[] types;
  final MethodHandle[] getters;
  /** DATA: {@code (Object,Object)void} setters. */
  final MethodHandle[] setters;
  /** RECORD: canonical constructor as {@code (Object[])Object}; DATA: {@code ()Object}. */
  final MethodHandle creator;
  /** RECORD and DATA: position of each name; ENUM (declaring class only): the constants. */
  final Map<String, Integer> index;
  final Map<String, Enum<?>> constants;

  private ClassModel(Class<?> type, Kind kind, String reason) {
    this(type, kind, reason, null, null, null, null, null, null);
  }

  private ClassModel(Class<?> type, Kind kind, String reason, String[] names, Class<?>[] types,
      MethodHandle[] getters, MethodHandle[] setters, MethodHandle creator,
      Map<String, Enum<?>> constants) {
    this.type = type;
    this.kind = kind;
    this.reason = reason;
    this.names = names;
    this.types = types;
    this.getters = getters;
    this.setters = setters;
    this.creator = creator;
    this.constants = constants;
    if (names == null) {
      this.index = null;
    } else {
      Map<String, Integer> idx = new HashMap<>();
      for (int i = 0; i < names.length; i++) {
        idx.put(names[i], i);
      }
      this.index = Map.copyOf(idx);
    }
  }

  static ClassModel of(Class<?> type) {
    return MODELS.get(type);
  }

  private static ClassModel build(Class<?> c) {
    Kind exact = EXACT.get(c);
    if (exact != null) {
      return new ClassModel(c, exact, null);
    }
    if (c.isArray()) {
      return new ClassModel(c, Kind.ARRAY, null); // primitive arrays are all in EXACT
    }
    if (Enum.class.isAssignableFrom(c)) {
      return enumModel(c);
    }
    if (Throwable.class.isAssignableFrom(c)) {
      return new ClassModel(c, Kind.THROWABLE, null);
    }
    if (Annotation.class.isAssignableFrom(c) && !c.isInterface()) {
      return new ClassModel(c, Kind.ANNOTATION, null);
    }
    if (List.class.isAssignableFrom(c)) {
      return new ClassModel(c, Kind.LIST, null);
    }
    if (Set.class.isAssignableFrom(c)) {
      return new ClassModel(c, Kind.SET, null);
    }
    if (Map.class.isAssignableFrom(c)) {
      return new ClassModel(c, Kind.MAP, null);
    }
    boolean serializable = Serializable.class.isAssignableFrom(c);
    if (Collection.class.isAssignableFrom(c)) { // queues and views: keep the class if we can
      return new ClassModel(c, serializable ? Kind.SERIALIZABLE : Kind.COLLECTION, null);
    }
    String reason;
    try {
      reason = c.isRecord() ? null : dataClassProblem(c);
      if (reason == null) {
        return c.isRecord() ? recordModel(c) : dataModel(c);
      }
    } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
      // RuntimeException covers InaccessibleObjectException; LinkageError a missing field type.
      reason = "its members are not accessible (" + e + ")";
    }
    return new ClassModel(c, serializable ? Kind.SERIALIZABLE : Kind.UNSUPPORTED, reason);
  }

  private static ClassModel enumModel(Class<?> c) {
    if (!c.isEnum()) { // a constant with a body: its values are encoded with the declaring class
      return new ClassModel(c, Kind.ENUM, null);
    }
    Map<String, Enum<?>> constants = new HashMap<>();
    try {
      for (Object constant : c.getEnumConstants()) { // initialises the class
        constants.put(((Enum<?>) constant).name(), (Enum<?>) constant);
      }
    } catch (RuntimeException | LinkageError e) {
      return new ClassModel(c, Kind.ENUM, "its constants are not available (" + e + ")");
    }
    return new ClassModel(c, Kind.ENUM, null, null, null, null, null, null, Map.copyOf(constants));
  }

  private static ClassModel recordModel(Class<?> c) throws ReflectiveOperationException {
    RecordComponent[] components = c.getRecordComponents();
    int n = components.length;
    String[] names = new String[n];
    Class<?>[] types = new Class<?>[n];
    MethodHandle[] getters = new MethodHandle[n];
    MethodHandles.Lookup lookup = MethodHandles.lookup();
    for (int i = 0; i < n; i++) {
      names[i] = components[i].getName();
      types[i] = components[i].getType();
      Method accessor = components[i].getAccessor();
      accessor.setAccessible(true);
      getters[i] = lookup.unreflect(accessor).asType(MethodType.methodType(Object.class, Object.class));
    }
    Constructor<?> canonical = c.getDeclaredConstructor(types);
    canonical.setAccessible(true);
    MethodHandle creator = lookup.unreflectConstructor(canonical)
        .asSpreader(Object[].class, n)
        .asType(MethodType.methodType(Object.class, Object[].class));
    return new ClassModel(c, Kind.RECORD, null, names, types, getters, null, creator, null);
  }

  /**
   * Why {@code c} is not a plain data class, or null if it is one: a concrete class with a
   * no-argument constructor (any access) whose hierarchy has none of the Java serialization hooks.
   */
  private static String dataClassProblem(Class<?> c) throws ReflectiveOperationException {
    if (c.isInterface() || c.isPrimitive() || Modifier.isAbstract(c.getModifiers())) {
      return "it is abstract";
    }
    if (c.isHidden() || Proxy.isProxyClass(c)) {
      return "it is a hidden or proxy class";
    }
    if (Externalizable.class.isAssignableFrom(c)) {
      return "it is Externalizable";
    }
    for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
      for (Method m : k.getDeclaredMethods()) {
        String hook = m.getName();
        int params = m.getParameterCount();
        boolean isHook =
            (hook.equals("writeObject") && params == 1 && m.getParameterTypes()[0] == ObjectOutputStream.class)
                || (hook.equals("readObject") && params == 1 && m.getParameterTypes()[0] == ObjectInputStream.class)
                || ((hook.equals("writeReplace") || hook.equals("readResolve")) && params == 0);
        if (isHook && !Modifier.isStatic(m.getModifiers())) {
          return k.getName() + " declares " + hook + "()";
        }
      }
    }
    try {
      c.getDeclaredConstructor();
    } catch (NoSuchMethodException e) {
      return "it has no no-argument constructor";
    }
    return null;
  }

  private static ClassModel dataModel(Class<?> c) throws ReflectiveOperationException {
    Deque<Class<?>> hierarchy = new ArrayDeque<>();
    for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
      hierarchy.push(k); // the topmost superclass ends up first
    }
    List<Field> fields = new ArrayList<>();
    for (Class<?> k : hierarchy) {
      for (Field f : k.getDeclaredFields()) {
        int mod = f.getModifiers();
        if (!Modifier.isStatic(mod) && !Modifier.isTransient(mod) && !f.isSynthetic()) {
          fields.add(f);
        }
      }
    }
    int n = fields.size();
    String[] names = new String[n];
    Class<?>[] types = new Class<?>[n];
    MethodHandle[] getters = new MethodHandle[n];
    MethodHandle[] setters = new MethodHandle[n];
    MethodHandles.Lookup lookup = MethodHandles.lookup();
    Set<String> shadowing = new HashSet<>();
    for (int i = n - 1; i >= 0; i--) { // subclass fields first: they keep the plain name
      Field f = fields.get(i);
      f.setAccessible(true);
      names[i] = shadowing.add(f.getName())
          ? f.getName()
          : f.getDeclaringClass().getName() + "#" + f.getName();
      types[i] = f.getType();
      getters[i] = lookup.unreflectGetter(f).asType(MethodType.methodType(Object.class, Object.class));
      setters[i] = lookup.unreflectSetter(f)
          .asType(MethodType.methodType(void.class, Object.class, Object.class));
    }
    Constructor<?> noArg = c.getDeclaredConstructor();
    noArg.setAccessible(true);
    MethodHandle creator =
        lookup.unreflectConstructor(noArg).asType(MethodType.methodType(Object.class));
    return new ClassModel(c, Kind.DATA, null, names, types, getters, setters, creator, null);
  }
}
