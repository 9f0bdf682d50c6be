package dev.trade.internal.codec;

import dev.trade.internal.registry.Types;
import dev.trade.TRADESerializationException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Modifier;
import java.util.Collection;
import java.util.Map;

/**
 * Decodes records and plain data classes: reads the named values, matches them to the class's
 * components or fields by name, checks their types and rebuilds the object through the cached
 * handles of its {@link ClassModel}. Names the class does not have are ignored and missing ones get
 * their default (records: zero or null; data classes: what the no-argument constructor leaves), so
 * that sender and receiver may hold slightly different versions of a class.
 */
final class Structs {
  private Structs() {}

  static Object readRecord(Decoder d) throws TRADESerializationException {
    String typeName = d.readName();
    ClassModel m = ClassModel.of(d.resolve(typeName));
    if (m.kind != ClassModel.Kind.RECORD) {
      throw new TRADESerializationException("Cannot decode " + typeName + " as a record: "
          + (m.type.isRecord() ? m.reason : "it is not a record here"));
    }
    Object[] values = new Object[m.names.length];
    boolean[] present = readFields(d, m, values);
    for (int i = 0; i < values.length; i++) {
      values[i] = present[i]
          ? fit(values[i], m.types[i], d.allowList, "component ", m.names[i], typeName)
          : Types.defaultValue(m.types[i]);
    }
    try {
      return (Object) m.creator.invokeExact(values);
    } catch (Throwable e) {
      throw failed(typeName, e);
    }
  }

  static Object readObject(Decoder d) throws TRADESerializationException {
    String typeName = d.readName();
    ClassModel m = ClassModel.of(d.resolve(typeName));
    if (m.kind != ClassModel.Kind.DATA) {
      throw new TRADESerializationException("Cannot decode " + typeName
          + " as a data class: " + (m.reason == null ? "it is a " + m.kind : m.reason));
    }
    Object[] values = new Object[m.names.length];
    boolean[] present = readFields(d, m, values);
    for (int i = 0; i < values.length; i++) {
      if (present[i]) {
        values[i] = fit(values[i], m.types[i], d.allowList, "field ", m.names[i], typeName);
      }
    }
    try {
      Object object = (Object) m.creator.invokeExact();
      for (int i = 0; i < values.length; i++) {
        if (present[i]) {
          m.setters[i].invokeExact(object, values[i]);
        }
      }
      return object;
    } catch (Throwable e) {
      throw failed(typeName, e);
    }
  }

  /** Reads {@code count, (name, value)*} into {@code values}; returns which names were present. */
  private static boolean[] readFields(Decoder d, ClassModel m, Object[] values)
      throws TRADESerializationException {
    int n = d.readElements(2);
    d.enter();
    boolean[] present = new boolean[values.length];
    for (int i = 0; i < n; i++) {
      d.nextElement(2);
      String name = d.readName();
      Object value = d.readValue();
      Integer index = m.index.get(name);
      if (index != null) {
        values[index] = value;
        present[index] = true;
      }
    }
    d.leave();
    return present;
  }

  /** Errors from user constructors are the user's; anything else becomes a decoding failure. */
  private static TRADESerializationException failed(String typeName, Throwable e) {
    if (e instanceof Error && !(e instanceof LinkageError)) {
      throw (Error) e;
    }
    return new TRADESerializationException(
        "Cannot decode a " + typeName + ": its constructor rejected the values (" + e + ")", e);
  }

  /**
   * Returns {@code value} if it fits a variable of {@code type}, a copy of a decoded collection or
   * map in the declared concrete class (for example a {@code TreeMap} field), or fails naming
   * {@code what + member + " of " + owner} (joined only then: this runs for every field).
   */
  static Object fit(Object value, Class<?> type, AllowList allowList, String what, String member,
      String owner) throws TRADESerializationException {
    if (type.isPrimitive()
        ? value != null && value.getClass() == Types.box(type)
        : value == null || type.isInstance(value)) {
      return value;
    }
    Object adapted = adapt(value, type, allowList);
    if (adapted != null) {
      return adapted;
    }
    throw new TRADESerializationException("Cannot decode " + what + member + " of " + owner
        + ": it is declared "
        + type.getTypeName() + " but the value is "
        + (value == null ? "null" : "a " + value.getClass().getName()));
  }

  @SuppressWarnings({"unchecked", "rawtypes"})
  private static Object adapt(Object value, Class<?> type, AllowList allowList) {
    boolean collection = value instanceof Collection && Collection.class.isAssignableFrom(type);
    boolean map = value instanceof Map && Map.class.isAssignableFrom(type);
    if (!(collection || map)
        || type.isInterface()
        || Modifier.isAbstract(type.getModifiers())
        || !allowList.isAllowed(type.getName())) {
      return null;
    }
    try {
      Constructor<?> constructor = type.getConstructor();
      Object target = constructor.newInstance();
      if (collection) {
        ((Collection) target).addAll((Collection) value);
      } else {
        ((Map) target).putAll((Map) value);
      }
      return target;
    } catch (ReflectiveOperationException | RuntimeException e) {
      return null; // no public no-argument constructor, or the elements do not fit (TreeSet)
    }
  }
}
