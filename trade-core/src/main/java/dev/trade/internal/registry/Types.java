package dev.trade.internal.registry;

import java.util.Map;

/** Type-name helpers shared by matching, argument checks and return conversion. Stateless. */
public final class Types {
  private static final Map<String, Class<?>> PRIMITIVES =
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

  private Types() {}

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

  /** The boxed class for a primitive (void → Void), the class itself otherwise. */
  public static Class<?> box(Class<?> c) {
    // Comparisons, not a map lookup: every call boxes its primitive parameter and return types.
    if (!c.isPrimitive()) {
      return c;
    } else if (c == int.class) {
      return Integer.class;
    } else if (c == boolean.class) {
      return Boolean.class;
    } else if (c == double.class) {
      return Double.class;
    } else if (c == long.class) {
      return Long.class;
    } else if (c == void.class) {
      return Void.class;
    } else if (c == float.class) {
      return Float.class;
    } else if (c == byte.class) {
      return Byte.class;
    } else if (c == short.class) {
      return Short.class;
    }
    return Character.class;
  }

  /** The primitive type (or {@code void}) with this name, or null. */
  public static Class<?> primitive(String name) {
    return PRIMITIVES.get(name);
  }

  /** The zero value of a primitive type, or null for reference types. */
  public static Object defaultValue(Class<?> type) {
    return DEFAULTS.get(type);
  }

  /**
   * Resolves a {@link Class#getTypeName()} (e.g. {@code int}, {@code java.lang.String[]},
   * {@code com.acme.Term[][]}) without initializing the class, or returns null when the class is not
   * known to {@code loader}.
   */
  public static Class<?> resolve(String typeName, ClassLoader loader) {
    Class<?> p = PRIMITIVES.get(typeName);
    if (p != null) {
      return p;
    }
    int dims = dimensions(typeName);
    String base = typeName.substring(0, typeName.length() - 2 * dims);
    Class<?> c = PRIMITIVES.get(base);
    if (c == null) {
      try {
        c = Class.forName(base, false, loader);
      } catch (ClassNotFoundException | LinkageError e) {
        return null;
      }
    }
    for (int i = 0; i < dims; i++) {
      c = c.arrayType();
    }
    return c;
  }

  /**
   * The {@link Class#getName()} form of a {@link Class#getTypeName()}: arrays in descriptor form
   * ({@code double[]} → {@code [D}, {@code java.lang.String[]} → {@code [Ljava.lang.String;}),
   * every other name unchanged. Pure text: no class is loaded.
   */
  public static String binaryName(String typeName) {
    if (!typeName.endsWith("[]")) {
      return typeName;
    }
    int dims = dimensions(typeName);
    String base = typeName.substring(0, typeName.length() - 2 * dims);
    String element;
    Class<?> p = PRIMITIVES.get(base);
    if (p != null) {
      element = p.arrayType().getName().substring(1); // "[I" → "I"
    } else {
      element = "L" + base + ";";
    }
    return "[".repeat(dims) + element;
  }

  /**
   * The name TRADE reports for a parameter type: {@link #binaryName}, with a primitive type replaced
   * by its box ({@code int} → {@code java.lang.Integer}).
   */
  public static String boxedBinaryName(String typeName) {
    Class<?> p = PRIMITIVES.get(typeName);
    return p != null ? box(p).getName() : binaryName(typeName);
  }

  /** How many {@code []} end a type name. */
  private static int dimensions(String typeName) {
    int dims = 0;
    for (int end = typeName.length(); typeName.startsWith("[]", end - 2); end -= 2) {
      dims++;
    }
    return dims;
  }

  /** True when a value of type {@code given} can be passed where {@code declared} is expected. */
  public static boolean accepts(Class<?> declared, Class<?> given) {
    return box(declared).isAssignableFrom(box(given));
  }
}
