package dev.trade.internal.codec;

import static dev.trade.internal.codec.ByteSink.INTS;
import static dev.trade.internal.codec.ByteSink.LONGS;
import static dev.trade.internal.codec.ByteSink.SHORTS;

import dev.trade.TRADESerializationException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.annotation.Annotation;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.Duration;
import java.time.Instant;
import java.util.Collection;
import java.util.Iterator;
import java.util.Map;
import java.util.UUID;

/**
 * Writes one value into a {@link ByteSink}: the state of a single {@link Codec#write} call (nesting
 * depth, start offset). Not thread-safe; a new encoder is made per call.
 */
final class Encoder {
  final ByteSink out;
  final Limits limits;
  final InfoBinding info;
  private final int start;
  private int depth;

  Encoder(ByteSink out, Limits limits, InfoBinding info) {
    this.out = out;
    this.limits = limits;
    this.info = info;
    this.start = out.size();
  }

  void writeValue(Object v) throws TRADESerializationException {
    if (v == null) {
      out.writeByte(Tags.NULL);
      return;
    }
    Class<?> c = v.getClass();
    if (c == String.class) { // the most common values first, without the model lookup
      writeString((String) v);
      return;
    }
    if (c == Integer.class) {
      out.writeByte(Tags.INT32);
      out.writeInt((Integer) v);
      return;
    }
    ClassModel m = ClassModel.of(c);
    switch (m.kind) {
      case BOOLEAN -> out.writeByte((Boolean) v ? Tags.TRUE : Tags.FALSE);
      case BYTE -> {
        out.writeByte(Tags.INT8);
        out.writeByte((Byte) v);
      }
      case SHORT -> {
        out.writeByte(Tags.INT16);
        out.writeShort((Short) v);
      }
      case LONG -> {
        out.writeByte(Tags.INT64);
        out.writeLong((Long) v);
      }
      case FLOAT -> {
        out.writeByte(Tags.FLOAT32);
        out.writeFloat((Float) v);
      }
      case DOUBLE -> {
        out.writeByte(Tags.FLOAT64);
        out.writeDouble((Double) v);
      }
      case CHAR -> {
        out.writeByte(Tags.CHAR);
        out.writeShort((Character) v);
      }
      case BYTES -> writeBytes((byte[]) v);
      case BOOLEANS -> writeBooleans((boolean[]) v);
      case SHORTS -> writeShorts((short[]) v);
      case CHARS -> writeChars((char[]) v);
      case INTS -> writeInts((int[]) v);
      case LONGS -> writeLongs((long[]) v);
      case FLOATS -> writeFloats((float[]) v);
      case DOUBLES -> writeDoubles((double[]) v);
      case ARRAY -> writeArray((Object[]) v);
      case BIG_INTEGER -> writeBigInteger(Tags.BIG_INTEGER, (BigInteger) v);
      case BIG_DECIMAL -> {
        out.writeByte(Tags.BIG_DECIMAL);
        out.writeInt(((BigDecimal) v).scale());
        writeBigInteger(-1, ((BigDecimal) v).unscaledValue());
      }
      case UUID -> {
        out.writeByte(Tags.UUID);
        out.writeLong(((UUID) v).getMostSignificantBits());
        out.writeLong(((UUID) v).getLeastSignificantBits());
      }
      case INSTANT -> {
        out.writeByte(Tags.INSTANT);
        out.writeLong(((Instant) v).getEpochSecond());
        out.writeInt(((Instant) v).getNano());
      }
      case DURATION -> {
        out.writeByte(Tags.DURATION);
        out.writeLong(((Duration) v).getSeconds());
        out.writeInt(((Duration) v).getNano());
      }
      case CLASS -> {
        out.writeByte(Tags.CLASS);
        out.writeText(((Class<?>) v).getName());
      }
      case ENUM -> {
        out.writeByte(Tags.ENUM);
        out.writeText(((Enum<?>) v).getDeclaringClass().getName());
        out.writeText(((Enum<?>) v).name());
      }
      case THROWABLE -> ThrowableCodec.write(this, (Throwable) v);
      case ANNOTATION -> AnnotationCodec.write(this, (Annotation) v);
      case LIST, COLLECTION -> writeCollection(Tags.LIST, (Collection<?>) v);
      case SET -> writeCollection(Tags.SET, (Collection<?>) v);
      case MAP -> writeMap((Map<?, ?>) v);
      default -> writeOther(v, m);
    }
  }

  private void writeString(String s) throws TRADESerializationException {
    checkRoom(s.length());
    if (s.length() > limits.maxElements() / 3) { // else even 3 bytes per char fit
      checkCount(ByteSink.utf8Length(s, s.length()), s);
    }
    out.writeByte(Tags.STRING);
    out.writeText(s);
  }

  /** Records, data classes, Serializable and unsupported classes, any of which may be a TSI. */
  private void writeOther(Object v, ClassModel m) throws TRADESerializationException {
    ServiceDescriptor d = info.describe(v);
    if (d != null) {
      enter(v);
      DescriptorCodec.write(this, d);
      depth--;
      return;
    }
    switch (m.kind) {
      case RECORD -> writeFields(Tags.RECORD, v, m, "component ");
      case DATA -> writeFields(Tags.OBJECT, v, m, "field ");
      case SERIALIZABLE -> JavaSerialization.write(this, v);
      default -> throw new TRADESerializationException(
          "Cannot encode " + m.type.getName() + ": it is not a record, a plain data class ("
              + (m.reason == null ? "unsupported kind" : m.reason) + ") or Serializable");
    }
  }

  private void writeFields(int tag, Object v, ClassModel m, String what)
      throws TRADESerializationException {
    enter(v);
    out.writeByte(tag);
    out.writeText(m.type.getName());
    out.writeVarUInt(m.names.length);
    for (int i = 0; i < m.names.length; i++) {
      Object field;
      try {
        field = (Object) m.getters[i].invokeExact(v);
      } catch (RuntimeException e) {
        throw new TRADESerializationException(
            "Cannot encode " + m.type.getName() + ": reading " + what + m.names[i] + " failed", e);
      } catch (Error e) {
        throw e;
      } catch (Throwable e) { // a checked exception thrown sneakily by an accessor
        throw new TRADESerializationException(
            "Cannot encode " + m.type.getName() + ": reading " + what + m.names[i] + " failed", e);
      }
      out.writeText(m.names[i]);
      try {
        writeValue(field);
      } catch (TRADESerializationException e) {
        throw new TRADESerializationException(
            e.getMessage() + "\n    in " + what + m.names[i] + " of " + m.type.getName(),
            e.getCause());
      }
    }
    depth--;
  }

  private void writeCollection(int tag, Collection<?> c) throws TRADESerializationException {
    enter(c);
    int n = checkCount(c.size(), c);
    out.writeByte(tag);
    out.writeVarUInt(n);
    Iterator<?> it = c.iterator();
    for (int i = 0; i < n; i++) {
      if (!it.hasNext()) {
        throw changed(c);
      }
      writeValue(it.next());
      checkRoom(0);
    }
    if (it.hasNext()) {
      throw changed(c);
    }
    depth--;
  }

  private void writeMap(Map<?, ?> map) throws TRADESerializationException {
    enter(map);
    int n = checkCount(map.size(), map);
    out.writeByte(Tags.MAP);
    out.writeVarUInt(n);
    Iterator<? extends Map.Entry<?, ?>> it = map.entrySet().iterator();
    for (int i = 0; i < n; i++) {
      if (!it.hasNext()) {
        throw changed(map);
      }
      Map.Entry<?, ?> e = it.next();
      writeValue(e.getKey());
      writeValue(e.getValue());
      checkRoom(0);
    }
    if (it.hasNext()) {
      throw changed(map);
    }
    depth--;
  }

  private static TRADESerializationException changed(Object container) {
    return new TRADESerializationException("Cannot encode " + container.getClass().getName()
        + ": it changed size while being encoded (modified concurrently?)");
  }

  private void writeArray(Object[] a) throws TRADESerializationException {
    enter(a);
    checkCount(a.length, a);
    out.writeByte(Tags.ARRAY);
    out.writeText(a.getClass().getComponentType().getName());
    out.writeVarUInt(a.length);
    for (Object element : a) {
      writeValue(element);
      checkRoom(0);
    }
    depth--;
  }

  /** Writes the tag (unless negative), varint length and two's-complement big-endian bytes. */
  private void writeBigInteger(int tag, BigInteger v) throws TRADESerializationException {
    byte[] bytes = v.toByteArray();
    checkCount(bytes.length, v);
    checkRoom(bytes.length);
    if (tag >= 0) {
      out.writeByte(tag);
    }
    out.writeVarUInt(bytes.length);
    out.writeBytes(bytes);
  }

  private void arrayHeader(int tag, Object array, int length, int elementSize)
      throws TRADESerializationException {
    checkCount(length, array);
    checkRoom((long) length * elementSize);
    out.writeByte(tag);
    out.writeVarUInt(length);
    out.ensureCapacity(length * elementSize);
  }

  private void writeBytes(byte[] a) throws TRADESerializationException {
    arrayHeader(Tags.BYTES, a, a.length, 1);
    out.writeBytes(a);
  }

  private void writeBooleans(boolean[] a) throws TRADESerializationException {
    arrayHeader(Tags.BOOLEANS, a, a.length, 1);
    byte[] b = out.buf;
    int p = out.size;
    for (boolean x : a) {
      b[p++] = (byte) (x ? 1 : 0);
    }
    out.size = p;
  }

  private void writeShorts(short[] a) throws TRADESerializationException {
    arrayHeader(Tags.SHORTS, a, a.length, 2);
    byte[] b = out.buf;
    int p = out.size;
    for (short x : a) {
      SHORTS.set(b, p, x);
      p += 2;
    }
    out.size = p;
  }

  private void writeChars(char[] a) throws TRADESerializationException {
    arrayHeader(Tags.CHARS, a, a.length, 2);
    byte[] b = out.buf;
    int p = out.size;
    for (char x : a) {
      SHORTS.set(b, p, (short) x);
      p += 2;
    }
    out.size = p;
  }

  private void writeInts(int[] a) throws TRADESerializationException {
    arrayHeader(Tags.INTS, a, a.length, 4);
    byte[] b = out.buf;
    int p = out.size;
    for (int x : a) {
      INTS.set(b, p, x);
      p += 4;
    }
    out.size = p;
  }

  private void writeLongs(long[] a) throws TRADESerializationException {
    arrayHeader(Tags.LONGS, a, a.length, 8);
    byte[] b = out.buf;
    int p = out.size;
    for (long x : a) {
      LONGS.set(b, p, x);
      p += 8;
    }
    out.size = p;
  }

  private void writeFloats(float[] a) throws TRADESerializationException {
    arrayHeader(Tags.FLOATS, a, a.length, 4);
    byte[] b = out.buf;
    int p = out.size;
    for (float x : a) {
      INTS.set(b, p, Float.floatToRawIntBits(x));
      p += 4;
    }
    out.size = p;
  }

  private void writeDoubles(double[] a) throws TRADESerializationException {
    arrayHeader(Tags.DOUBLES, a, a.length, 8);
    byte[] b = out.buf;
    int p = out.size;
    for (double x : a) {
      LONGS.set(b, p, Double.doubleToRawLongBits(x));
      p += 8;
    }
    out.size = p;
  }

  /** Enters a container; fails when the nesting gets deeper than the limit (usually a cycle). */
  void enter(Object container) throws TRADESerializationException {
    if (++depth > limits.maxDepth()) {
      throw new TRADESerializationException("Cannot encode " + container.getClass().getName()
          + ": values nest deeper than " + limits.maxDepth() + " levels (a cyclic reference?)");
    }
  }

  void leave() {
    depth--;
  }

  /** Returns {@code n}, or fails if it is more elements (or bytes) than a decoder accepts. */
  int checkCount(int n, Object container) throws TRADESerializationException {
    if (n > limits.maxElements()) {
      throw new TRADESerializationException("Cannot encode " + container.getClass().getName()
          + ": its " + n + " elements exceed the limit of " + limits.maxElements());
    }
    return n;
  }

  /** Fails if {@code extra} more bytes would make the value longer than {@code maxBytes}. */
  void checkRoom(long extra) throws TRADESerializationException {
    long size = (long) out.size - start + extra;
    if (size > limits.maxBytes()) {
      throw new TRADESerializationException(
          "Cannot encode value: it needs more than the limit of " + limits.maxBytes() + " bytes");
    }
  }
}
