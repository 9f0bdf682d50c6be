package dev.trade.examples;

import java.lang.reflect.Array;
import java.lang.reflect.Constructor;
import java.lang.reflect.GenericArrayType;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.lang.reflect.TypeVariable;
import java.lang.reflect.WildcardType;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;

/**
 * Just enough JSON for {@link CallService}'s arguments: parses a text into maps, lists, strings,
 * numbers, booleans and null, and builds values of a parameter's type from them (records from
 * objects, arrays, lists and sets from arrays, maps from objects). Stateless.
 */
final class Json {
  /** The key by which a JSON object names its class. */
  static final String TYPE_KEY = "@type";

  /** The element type of a raw {@code List} or {@code Map}: the signature does not say it. */
  private static final Type UNKNOWN = new Type() {
    @Override
    public String getTypeName() {
      return "?";
    }
  };

  private final String text;
  private int pos;

  private Json(String text) {
    this.text = text;
  }

  /**
   * The value of {@code text}.
   *
   * @throws IllegalArgumentException naming the position of a syntax error
   */
  static Object parse(String text) {
    Json p = new Json(text);
    Object v = p.value();
    p.blanks();
    if (p.pos != text.length()) {
      throw p.error("unexpected text after the value");
    }
    return v;
  }

  /**
   * A value of {@code type} built from a parsed JSON value. A JSON object may name its class with
   * {@code "@type"} (a record, or {@code java.util.Map}); it must where nothing else says what it
   * is: as an element of a list or map whose element type {@code type} does not give (a raw
   * {@code List}, as service infos describe parameters).
   *
   * @param type the parameter's type, generic when known
   * @throws IllegalArgumentException saying what does not fit, and where
   */
  static Object to(Type type, Object json) {
    return to(type, json, "");
  }

  private static Object to(Type type, Object json, String at) {
    if (json instanceof Map<?, ?> map && map.containsKey(TYPE_KEY)) {
      type = named(map.get(TYPE_KEY), raw(type), at);
      Map<Object, Object> rest = new LinkedHashMap<>(map);
      rest.remove(TYPE_KEY);
      json = rest;
    }
    Class<?> raw = raw(type);
    if (json == null) {
      if (raw.isPrimitive()) {
        throw new IllegalArgumentException(where(at) + "null for a " + raw.getName());
      }
      return null;
    }
    if (type == UNKNOWN && json instanceof Map) {
      throw new IllegalArgumentException(where(at) + "a JSON object, but the signature does not say"
          + " what it is (service infos carry raw parameter types, such as java.util.List): name its"
          + " class, {\"@type\": \"com.acme.Pose\", ...} ({\"@type\": \"java.util.Map\", ...} for a"
          + " map), or pass --types with a class on the class path that declares the method");
    }
    if (raw == Object.class) {
      return json instanceof Double d ? narrow(d) : json instanceof List<?> list
          ? list(type, list, at) : json instanceof Map<?, ?> map ? map(type, map, at) : json;
    }
    if (raw.isArray() && json instanceof List<?> list) {
      Type component = type instanceof GenericArrayType g ? g.getGenericComponentType()
          : raw.getComponentType();
      Object array = Array.newInstance(raw.getComponentType(), list.size());
      for (int i = 0; i < list.size(); i++) {
        Array.set(array, i, to(component, list.get(i), at + "[" + i + "]"));
      }
      return array;
    }
    if (json instanceof List<?> list && (raw.isAssignableFrom(ArrayList.class)
        || raw.isAssignableFrom(LinkedHashSet.class))) {
      List<Object> values = list(element(type, 0), list, at);
      return raw.isAssignableFrom(ArrayList.class) ? values : new LinkedHashSet<>(values);
    }
    if (json instanceof Map<?, ?> map && raw.isAssignableFrom(LinkedHashMap.class)) {
      return map(element(type, 1), map, at);
    }
    if (raw.isRecord() && json instanceof Map<?, ?> map) {
      return record(raw, map, at);
    }
    if (json instanceof Double d) {
      return number(raw, d, at);
    }
    if (raw.isInstance(json) || raw == boolean.class && json instanceof Boolean) {
      return json;
    }
    throw new IllegalArgumentException(where(at) + "a " + describe(json) + " is not a "
        + type.getTypeName());
  }

  private static List<Object> list(Type element, List<?> list, String at) {
    List<Object> result = new ArrayList<>();
    for (int i = 0; i < list.size(); i++) {
      result.add(to(element, list.get(i), at + "[" + i + "]"));
    }
    return result;
  }

  private static Map<String, Object> map(Type value, Map<?, ?> map, String at) {
    Map<String, Object> result = new LinkedHashMap<>();
    map.forEach((k, v) -> result.put((String) k, to(value, v, at + "." + k)));
    return result;
  }

  /** The type argument {@code i} of {@code type}, or {@link #UNKNOWN} when {@code type} is raw. */
  private static Type element(Type type, int i) {
    if (type instanceof ParameterizedType p && p.getActualTypeArguments().length > i) {
      return p.getActualTypeArguments()[i];
    }
    return UNKNOWN;
  }

  /** The class a JSON object's {@code "@type"} names, checked against what is expected there. */
  private static Class<?> named(Object name, Class<?> expected, String at) {
    if (!(name instanceof String className)) {
      throw new IllegalArgumentException(where(at) + "\"@type\" must be a class name, not " + name);
    }
    Class<?> c;
    try {
      c = Class.forName(className, false, Json.class.getClassLoader());
    } catch (ClassNotFoundException | LinkageError e) {
      throw new IllegalArgumentException(where(at) + "\"@type\" names " + className
          + ", which is not on the class path; add it with java -cp");
    }
    if (!c.isRecord() && c != Map.class) {
      throw new IllegalArgumentException(where(at) + "\"@type\" names " + className
          + ", which is neither a record nor java.util.Map");
    }
    if (!expected.isAssignableFrom(c)) {
      throw new IllegalArgumentException(where(at) + "\"@type\" names " + className
          + ", which is not a " + expected.getTypeName());
    }
    return c;
  }

  private static Class<?> raw(Type type) {
    if (type instanceof Class<?> c) {
      return c;
    } else if (type instanceof ParameterizedType p) {
      return (Class<?>) p.getRawType();
    } else if (type instanceof GenericArrayType g) {
      return Array.newInstance(raw(g.getGenericComponentType()), 0).getClass();
    } else if (type instanceof WildcardType w) {
      return raw(w.getUpperBounds()[0]);
    } else if (type instanceof TypeVariable<?> v) {
      return raw(v.getBounds()[0]);
    }
    return Object.class; // UNKNOWN
  }

  private static String where(String at) {
    return at.isEmpty() ? "" : "at " + at + ": ";
  }

  private static Object narrow(double d) {
    if (d != Math.rint(d) || Math.abs(d) >= 1e15) {
      return d;
    }
    return d >= Integer.MIN_VALUE && d <= Integer.MAX_VALUE ? (Object) (int) d : (Object) (long) d;
  }

  private static Object number(Class<?> type, double d, String at) {
    boolean whole = d == Math.rint(d);
    if ((type == int.class || type == Integer.class) && whole && d == (int) d) {
      return (int) d;
    } else if ((type == long.class || type == Long.class) && whole && d == (long) d) {
      return (long) d;
    } else if ((type == short.class || type == Short.class) && whole && d == (short) d) {
      return (short) d;
    } else if ((type == byte.class || type == Byte.class) && whole && d == (byte) d) {
      return (byte) d;
    } else if (type == double.class || type == Double.class || type == Number.class) {
      return d;
    } else if (type == float.class || type == Float.class) {
      return (float) d;
    }
    throw new IllegalArgumentException(where(at) + d + " is not a " + type.getTypeName());
  }

  private static Object record(Class<?> type, Map<?, ?> map, String at) {
    RecordComponent[] components = type.getRecordComponents();
    Class<?>[] types = new Class<?>[components.length];
    Object[] values = new Object[components.length];
    for (int i = 0; i < components.length; i++) {
      types[i] = components[i].getType();
      String name = components[i].getName();
      if (!map.containsKey(name)) {
        throw new IllegalArgumentException(where(at) + "no \"" + name + "\" for "
            + type.getSimpleName() + " " + map.keySet());
      }
      // The record's own declaration gives its components' generic types.
      values[i] = to(components[i].getGenericType(), map.get(name), at + "." + name);
    }
    try {
      Constructor<?> c = type.getDeclaredConstructor(types);
      c.setAccessible(true);
      return c.newInstance(values);
    } catch (ReflectiveOperationException | RuntimeException e) {
      throw new IllegalArgumentException(where(at) + "cannot make a " + type.getSimpleName()
          + ": " + e, e);
    }
  }

  private static String describe(Object json) {
    return json instanceof Map ? "JSON object" : json instanceof Collection ? "JSON array"
        : json instanceof String ? "string" : json.getClass().getSimpleName().toLowerCase();
  }

  private Object value() {
    blanks();
    if (pos >= text.length()) {
      throw error("a value is missing");
    }
    char c = text.charAt(pos);
    if (c == '{') {
      return object();
    } else if (c == '[') {
      return array();
    } else if (c == '"') {
      return string();
    } else if (text.startsWith("true", pos) || text.startsWith("false", pos)
        || text.startsWith("null", pos)) {
      String word = text.startsWith("true", pos) ? "true" : text.startsWith("false", pos) ? "false" : "null";
      pos += word.length();
      return word.equals("null") ? null : Boolean.valueOf(word);
    }
    int start = pos;
    while (pos < text.length() && "+-.eE0123456789".indexOf(text.charAt(pos)) >= 0) {
      pos++;
    }
    try {
      return Double.valueOf(text.substring(start, pos));
    } catch (NumberFormatException e) {
      pos = start;
      throw error("expected a JSON value");
    }
  }

  private Map<String, Object> object() {
    Map<String, Object> map = new LinkedHashMap<>();
    pos++;
    if (next() == '}') {
      pos++;
      return map;
    }
    while (true) {
      if (next() != '"') {
        throw error("expected a \"name\"");
      }
      String key = string();
      expect(':');
      map.put(key, value());
      if (next() == '}') {
        pos++;
        return map;
      }
      expect(',');
    }
  }

  private List<Object> array() {
    List<Object> list = new ArrayList<>();
    pos++;
    if (next() == ']') {
      pos++;
      return list;
    }
    while (true) {
      list.add(value());
      if (next() == ']') {
        pos++;
        return list;
      }
      expect(',');
    }
  }

  private String string() {
    StringBuilder sb = new StringBuilder();
    pos++;
    while (pos < text.length()) {
      char c = text.charAt(pos++);
      if (c == '"') {
        return sb.toString();
      }
      if (c != '\\') {
        sb.append(c);
      } else if (pos < text.length()) {
        char e = text.charAt(pos++);
        switch (e) {
          case 'n' -> sb.append('\n');
          case 't' -> sb.append('\t');
          case 'r' -> sb.append('\r');
          case 'b' -> sb.append('\b');
          case 'f' -> sb.append('\f');
          case 'u' -> {
            if (pos + 4 > text.length()) {
              throw error("a \\u escape needs four hex digits");
            }
            sb.append((char) Integer.parseInt(text.substring(pos, pos + 4), 16));
            pos += 4;
          }
          default -> sb.append(e);
        }
      }
    }
    throw error("a string is not closed");
  }

  private char next() {
    blanks();
    if (pos >= text.length()) {
      throw error("the text ends early");
    }
    return text.charAt(pos);
  }

  private void expect(char c) {
    if (next() != c) {
      throw error("expected '" + c + "'");
    }
    pos++;
  }

  private void blanks() {
    while (pos < text.length() && Character.isWhitespace(text.charAt(pos))) {
      pos++;
    }
  }

  private IllegalArgumentException error(String what) {
    return new IllegalArgumentException("JSON: " + what + " at position " + pos + " of " + text);
  }
}
