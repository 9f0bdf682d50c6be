package dev.trade.internal.codec;

import java.util.Map;

/** Facts about the eight primitive types and {@code void} that reflection does not offer directly. */
final class Primitives {
  private static final Map<String, Class<?>> BY_NAME =
      Map.of(
          "boolean", boolean.class,
          "byte", byte.class,
          "short", short.class,
          "char", char.class,
          "int", int.class,
          "long", long.class,
          "float", float.class,
          "double", double.class,
          "void", void.class);

  private static final Map<Class<?>, Class<?>> WRAPPERS =
      Map.of(
          boolean.class, Boolean.class,
          byte.class, Byte.class,
          short.class, Short.class,
          char.class, Character.class,
          int.class, Integer.class,
          long.class, Long.class,
          float.class, Float.class,
          double.class, Double.class,
          void.class, Void.class);

  private static final Map<Class<?>, Object> DEFAULTS =
      Map.of(
          boolean.class, false,
          byte.class, (byte) 0,
          short.class, (short) 0,
          char.class, (char) 0,
          int.class, 0,
          long.class, 0L,
          float.class, 0f,
          double.class, 0d);

  private Primitives() {}

  /** The primitive type (or {@code void}) with this name, or null. */
  static Class<?> named(String name) {
    return BY_NAME.get(name);
  }

  /** The wrapper class of a primitive type, or {@code type} itself for reference types. */
  static Class<?> wrap(Class<?> type) {
    return type.isPrimitive() ? WRAPPERS.get(type) : type;
  }

  /** The zero value of a primitive type, or null for reference types. */
  static Object defaultValue(Class<?> type) {
    return DEFAULTS.get(type);
  }
}
