package dev.trade.internal.codec;

import dev.trade.TRADESerializationException;
import java.lang.reflect.Array;
import java.lang.reflect.InvocationHandler;
import java.lang.reflect.Method;
import java.lang.reflect.Proxy;
import java.util.Arrays;

/**
 * Behaviour of a decoded annotation: members return the decoded values (arrays as fresh copies),
 * and {@code equals}, {@code hashCode}, {@code toString} and {@code annotationType} follow the
 * {@link java.lang.annotation.Annotation} contract, so a decoded annotation equals the compiler's
 * instance of the same annotation and the other way round.
 *
 * <p>Immutable and safe for concurrent use.
 */
final class AnnotationHandler implements InvocationHandler {
  private final AnnotationCodec.Members members;
  /** One value per member, in the order of {@code members.names}; never null. */
  private final Object[] values;

  AnnotationHandler(AnnotationCodec.Members members, Object[] values) {
    this.members = members;
    this.values = values;
  }

  @Override
  public Object invoke(Object proxy, Method method, Object[] args) {
    String name = method.getName();
    int count = method.getParameterCount();
    if (count == 1 && name.equals("equals") && method.getParameterTypes()[0] == Object.class) {
      return equalTo(proxy, args[0]);
    }
    if (count == 0) {
      switch (name) {
        case "hashCode":
          return hash();
        case "toString":
          return text();
        case "annotationType":
          return members.type;
        default:
          int i = members.indexOf(name);
          if (i >= 0) {
            return copyOf(values[i]);
          }
      }
    }
    throw new UnsupportedOperationException("annotation proxy has no method " + method);
  }

  private boolean equalTo(Object proxy, Object other) {
    if (other == proxy) {
      return true;
    }
    if (!members.type.isInstance(other)) {
      return false;
    }
    if (Proxy.isProxyClass(other.getClass())
        && Proxy.getInvocationHandler(other) instanceof AnnotationHandler) {
      Object[] theirs = ((AnnotationHandler) Proxy.getInvocationHandler(other)).values;
      for (int i = 0; i < values.length; i++) {
        if (!memberEquals(values[i], theirs[i])) {
          return false;
        }
      }
      return true;
    }
    for (int i = 0; i < values.length; i++) {
      try {
        if (!memberEquals(values[i], members.get(i, other))) {
          return false;
        }
      } catch (TRADESerializationException e) {
        return false;
      }
    }
    return true;
  }

  private static boolean memberEquals(Object a, Object b) {
    if (!a.getClass().isArray()) {
      return a.equals(b);
    }
    if (b == null || a.getClass() != b.getClass()) {
      return false;
    }
    if (a instanceof Object[]) {
      return Arrays.equals((Object[]) a, (Object[]) b);
    }
    if (a instanceof int[]) {
      return Arrays.equals((int[]) a, (int[]) b);
    }
    if (a instanceof long[]) {
      return Arrays.equals((long[]) a, (long[]) b);
    }
    if (a instanceof byte[]) {
      return Arrays.equals((byte[]) a, (byte[]) b);
    }
    if (a instanceof short[]) {
      return Arrays.equals((short[]) a, (short[]) b);
    }
    if (a instanceof char[]) {
      return Arrays.equals((char[]) a, (char[]) b);
    }
    if (a instanceof boolean[]) {
      return Arrays.equals((boolean[]) a, (boolean[]) b);
    }
    if (a instanceof float[]) {
      return Arrays.equals((float[]) a, (float[]) b);
    }
    return Arrays.equals((double[]) a, (double[]) b);
  }

  /** The sum of {@code (127 * name.hashCode()) ^ valueHash} over the members, as specified. */
  private int hash() {
    int h = 0;
    for (int i = 0; i < values.length; i++) {
      h += (127 * members.names[i].hashCode()) ^ valueHash(values[i]);
    }
    return h;
  }

  private static int valueHash(Object v) {
    if (!v.getClass().isArray()) {
      return v.hashCode();
    }
    if (v instanceof Object[]) {
      return Arrays.hashCode((Object[]) v);
    }
    if (v instanceof int[]) {
      return Arrays.hashCode((int[]) v);
    }
    if (v instanceof long[]) {
      return Arrays.hashCode((long[]) v);
    }
    if (v instanceof byte[]) {
      return Arrays.hashCode((byte[]) v);
    }
    if (v instanceof short[]) {
      return Arrays.hashCode((short[]) v);
    }
    if (v instanceof char[]) {
      return Arrays.hashCode((char[]) v);
    }
    if (v instanceof boolean[]) {
      return Arrays.hashCode((boolean[]) v);
    }
    if (v instanceof float[]) {
      return Arrays.hashCode((float[]) v);
    }
    return Arrays.hashCode((double[]) v);
  }

  private String text() {
    StringBuilder sb = new StringBuilder("@").append(members.type.getName()).append('(');
    for (int i = 0; i < values.length; i++) {
      sb.append(i == 0 ? "" : ", ").append(members.names[i]).append('=');
      appendValue(sb, values[i]);
    }
    return sb.append(')').toString();
  }

  private static void appendValue(StringBuilder sb, Object v) {
    if (v.getClass().isArray()) {
      sb.append('{');
      for (int i = 0, n = Array.getLength(v); i < n; i++) {
        appendValue(sb.append(i == 0 ? "" : ", "), Array.get(v, i));
      }
      sb.append('}');
    } else if (v instanceof String) {
      sb.append('"').append(((String) v).replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
    } else if (v instanceof Character) {
      sb.append('\'').append(v).append('\'');
    } else if (v instanceof Class) {
      sb.append(((Class<?>) v).getName()).append(".class");
    } else if (v instanceof Long) {
      sb.append(v).append('L');
    } else if (v instanceof Float) {
      sb.append(v).append('f');
    } else if (v instanceof Enum) {
      sb.append(((Enum<?>) v).name());
    } else {
      sb.append(v);
    }
  }

  private static Object copyOf(Object v) {
    if (!v.getClass().isArray() || Array.getLength(v) == 0) {
      return v;
    }
    if (v instanceof Object[]) {
      return ((Object[]) v).clone();
    }
    Object copy = Array.newInstance(v.getClass().getComponentType(), Array.getLength(v));
    System.arraycopy(v, 0, copy, 0, Array.getLength(v));
    return copy;
  }
}
