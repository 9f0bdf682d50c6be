package dev.trade.internal.system;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Types;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Service constraints as plain values (a map of lists and strings, docs/protocol.md "Service
 * constraints"), so that a peer in any language can pass them to a system service: the one place
 * that reads and writes that form. Stateless and thread-safe.
 */
public final class ConstraintsForm {
  /** The form's keys, in the order {@link #encode} writes them. */
  static final List<String> KEYS = List.of("name", "argTypes", "returnType", "inGroups",
      "notInGroups", "local", "host", "onLocalhost", "notOnHost", "not", "or");
  /** How deeply {@code not} and {@code or} may nest: deeper forms are refused, not recursed into. */
  static final int MAX_DEPTH = 8;

  private ConstraintsForm() {}

  /**
   * The form of {@code q}: a map holding only the constraints that are set, keys in {@link #KEYS}
   * order; an empty map matches every service.
   */
  public static Map<String, Object> encode(Query q) {
    Map<String, Object> m = new LinkedHashMap<>();
    putIf(m, "name", q.name());
    if (q.argTypes() != null) {
      List<Object> types = new ArrayList<>();
      q.argTypes().forEach(t -> types.add(t.getTypeName()));
      m.put("argTypes", types);
    }
    putIf(m, "returnType", q.returnType() == null ? null : q.returnType().getTypeName());
    putIf(m, "inGroups", q.inGroups().isEmpty() ? null : new ArrayList<Object>(q.inGroups()));
    putIf(m, "notInGroups", q.notInGroups().isEmpty() ? null : new ArrayList<Object>(q.notInGroups()));
    putIf(m, "local", q.local() ? Boolean.TRUE : null);
    putIf(m, "host", q.host());
    putIf(m, "onLocalhost", q.localhost());
    putIf(m, "notOnHost", q.notOnHosts().isEmpty() ? null : new ArrayList<Object>(q.notOnHosts()));
    putIf(m, "not", q.negations().isEmpty() ? null : encodeAll(q.negations()));
    putIf(m, "or", q.alternatives().isEmpty() ? null : encodeAll(q.alternatives()));
    return m;
  }

  /**
   * Whether {@code argument} is in this form (a map) rather than a Java constraints object or null.
   */
  public static boolean isForm(Object argument) {
    return argument instanceof Map;
  }

  /**
   * Reads the form. Type names are resolved without initialising a class, by this thread's context
   * loader or TRADE's own.
   *
   * @param form a map as docs/protocol.md describes
   * @return new constraints matching what the form says
   * @throws TRADEBadArgumentsException naming the key (its path, as {@code or[0].argTypes[1]}) that
   *     is not as the form requires, and what it must be
   */
  public static TRADEServiceConstraints decode(Object form) throws TRADEBadArgumentsException {
    return decode(form, "constraints", 0);
  }

  private static TRADEServiceConstraints decode(Object form, String path, int depth)
      throws TRADEBadArgumentsException {
    if (!(form instanceof Map)) {
      throw bad(path, "must be a map of constraints", form);
    }
    if (depth > MAX_DEPTH) {
      throw new TRADEBadArgumentsException("Constraints: " + path + " nests 'not' and 'or' deeper"
          + " than " + MAX_DEPTH + " levels");
    }
    TRADEServiceConstraints c = new TRADEServiceConstraints();
    for (Map.Entry<?, ?> e : ((Map<?, ?>) form).entrySet()) {
      if (!(e.getKey() instanceof String) || !KEYS.contains(e.getKey())) {
        throw new TRADEBadArgumentsException("Constraints: " + path + " has an unknown key "
            + describe(e.getKey()) + "; the keys are " + String.join(", ", KEYS));
      }
      String key = (String) e.getKey();
      String at = path + "." + key;
      Object v = e.getValue();
      if (v == null) {
        continue; // null is the same as absent
      }
      switch (key) {
        case "name":
          c.name(text(v, at));
          break;
        case "argTypes":
          List<String> names = texts(v, at);
          Class<?>[] types = new Class<?>[names.size()];
          for (int i = 0; i < types.length; i++) {
            types[i] = type(names.get(i), at + "[" + i + "]");
          }
          c.argTypes(types);
          break;
        case "returnType":
          c.returnType(type(text(v, at), at));
          break;
        case "inGroups":
          c.inGroups(texts(v, at).toArray(new String[0]));
          break;
        case "notInGroups":
          c.notInGroups(texts(v, at).toArray(new String[0]));
          break;
        case "local":
          if (bool(v, at)) {
            c.local();
          }
          break;
        case "host":
          c.host(text(v, at));
          break;
        case "onLocalhost":
          if (bool(v, at)) {
            c.onLocalhost();
          } else {
            c.notOnLocalhost();
          }
          break;
        case "notOnHost":
          c.notOnHost(texts(v, at).toArray(new String[0]));
          break;
        default: // "not" and "or"
          int i = 0;
          for (Object sub : collection(v, at)) {
            TRADEServiceConstraints s = decode(sub, at + "[" + i++ + "]", depth + 1);
            if (key.equals("not")) {
              c.not(s);
            } else {
              c.or(s);
            }
          }
      }
    }
    return c;
  }

  private static List<Object> encodeAll(List<Query> queries) {
    List<Object> all = new ArrayList<>();
    queries.forEach(q -> all.add(encode(q)));
    return all;
  }

  private static void putIf(Map<String, Object> m, String key, Object value) {
    if (value != null) {
      m.put(key, value);
    }
  }

  private static String text(Object v, String at) throws TRADEBadArgumentsException {
    if (!(v instanceof String) || ((String) v).isEmpty()) {
      throw bad(at, "must be a non-empty string", v);
    }
    return (String) v;
  }

  private static boolean bool(Object v, String at) throws TRADEBadArgumentsException {
    if (!(v instanceof Boolean)) {
      throw bad(at, "must be true or false", v);
    }
    return (Boolean) v;
  }

  private static Collection<?> collection(Object v, String at) throws TRADEBadArgumentsException {
    if (!(v instanceof List) && !(v instanceof java.util.Set)) {
      throw bad(at, "must be a list", v);
    }
    return (Collection<?>) v;
  }

  private static List<String> texts(Object v, String at) throws TRADEBadArgumentsException {
    List<String> result = new ArrayList<>();
    for (Object o : collection(v, at)) {
      result.add(text(o, at + "[" + result.size() + "]"));
    }
    return result;
  }

  private static Class<?> type(String name, String at) throws TRADEBadArgumentsException {
    ClassLoader context = Thread.currentThread().getContextClassLoader();
    Class<?> c = context == null ? null : Types.resolve(name, context);
    if (c == null) {
      c = Types.resolve(name, ConstraintsForm.class.getClassLoader());
    }
    if (c == null) {
      throw new TRADEBadArgumentsException("Constraints: " + at + " names type '" + name + "', which"
          + " is not known here; give a type name as Class.getTypeName() spells it (int,"
          + " java.lang.String, double[])");
    }
    return c;
  }

  private static TRADEBadArgumentsException bad(String at, String must, Object got) {
    return new TRADEBadArgumentsException("Constraints: " + at + " " + must + "; got "
        + describe(got));
  }

  private static String describe(Object v) {
    if (v == null) {
      return "null";
    }
    return v instanceof String ? "'" + v + "'" : v.getClass().getName() + " " + v;
  }
}
