package dev.trade.examples;

import java.lang.reflect.Array;
import java.lang.reflect.Constructor;
import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Just enough JSON for {@link CallService}'s arguments: parses a text into maps, lists, strings,
 * numbers, booleans and null, and builds values of a parameter's type from them (records from
 * objects, arrays and lists from arrays). Stateless.
 */
final class Json {
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
   * A value of {@code type} built from a parsed JSON value.
   *
   * @throws IllegalArgumentException saying what does not fit
   */
  static Object to(Class<?> type, Object json) {
    if (json == null) {
      if (type.isPrimitive()) {
        throw new IllegalArgumentException("null for a " + type.getName());
      }
      return null;
    }
    if (type == Object.class) {
      return json instanceof Double d && d == Math.rint(d) && Math.abs(d) < 1e15 ? narrow(d) : json;
    }
    if (type.isArray() && json instanceof List<?> list) {
      Object array = Array.newInstance(type.getComponentType(), list.size());
      for (int i = 0; i < list.size(); i++) {
        Array.set(array, i, to(type.getComponentType(), list.get(i)));
      }
      return array;
    }
    if (type.isAssignableFrom(ArrayList.class) && json instanceof List<?> list) {
      List<Object> result = new ArrayList<>();
      list.forEach(e -> result.add(to(Object.class, e)));
      return result;
    }
    if (type.isRecord() && json instanceof Map<?, ?> map) {
      return record(type, map);
    }
    if (json instanceof Double d) {
      return number(type, d);
    }
    if (type.isInstance(json) || type == boolean.class && json instanceof Boolean) {
      return json;
    }
    throw new IllegalArgumentException("a " + describe(json) + " is not a " + type.getTypeName());
  }

  private static Object narrow(double d) {
    return d >= Integer.MIN_VALUE && d <= Integer.MAX_VALUE ? (Object) (int) d : (Object) (long) d;
  }

  private static Object number(Class<?> type, double d) {
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
    throw new IllegalArgumentException(d + " is not a " + type.getTypeName());
  }

  private static Object record(Class<?> type, Map<?, ?> map) {
    RecordComponent[] components = type.getRecordComponents();
    Class<?>[] types = new Class<?>[components.length];
    Object[] values = new Object[components.length];
    for (int i = 0; i < components.length; i++) {
      types[i] = components[i].getType();
      if (!map.containsKey(components[i].getName())) {
        throw new IllegalArgumentException("no \"" + components[i].getName() + "\" for "
            + type.getSimpleName() + " " + map.keySet());
      }
      values[i] = to(types[i], map.get(components[i].getName()));
    }
    try {
      Constructor<?> c = type.getDeclaredConstructor(types);
      c.setAccessible(true);
      return c.newInstance(values);
    } catch (ReflectiveOperationException | RuntimeException e) {
      throw new IllegalArgumentException("cannot make a " + type.getSimpleName() + ": " + e, e);
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
