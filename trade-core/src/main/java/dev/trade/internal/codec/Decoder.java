package dev.trade.internal.codec;

import dev.trade.internal.registry.Types;
import static dev.trade.internal.codec.ByteSink.INTS;
import static dev.trade.internal.codec.ByteSink.LONGS;
import static dev.trade.internal.codec.ByteSink.SHORTS;

import dev.trade.TRADESerializationException;
import java.lang.reflect.Array;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.DateTimeException;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;

/**
 * Reads one value from a {@link ByteSource}: the state of a single {@link Codec#read} call. Every
 * count is checked against {@link Limits} and against the bytes actually left before anything is
 * allocated, and every nesting level against {@code maxDepth}. Counts are checked together, not
 * each alone: the elements still to come of every container being read need their bytes too
 * ({@link #pending}), so a value of nested lists, each claiming about as many elements as bytes
 * are left, cannot make each level pre-size a collection for the same bytes. Not thread-safe.
 */
final class Decoder {
  final ByteSource in;
  final Limits limits;
  /** Replaced for the members of an annotation (see {@link AnnotationCodec}), then restored. */
  AllowList allowList;
  final InfoBinding info;
  final ClassLoader loader;
  private final TypeCache types;
  private final boolean javaSerialization;
  private int depth;
  /**
   * The least bytes that the elements still to come of the containers being read need: those
   * bytes are taken, and a count inside an element may claim only what is left beside them.
   */
  private long pending;

  Decoder(ByteSource in, Limits limits, AllowList allowList, InfoBinding info, ClassLoader loader,
      TypeCache types, boolean javaSerialization) {
    this.in = in;
    this.limits = limits;
    this.allowList = allowList;
    this.info = info;
    this.loader = loader;
    this.types = types;
    this.javaSerialization = javaSerialization;
  }

  Object readValue() throws TRADESerializationException {
    int tag = in.readUnsignedByte();
    switch (tag) {
      case Tags.NULL: return null;
      case Tags.FALSE: return Boolean.FALSE;
      case Tags.TRUE: return Boolean.TRUE;
      case Tags.INT8: return in.readByte();
      case Tags.INT16: return in.readShort();
      case Tags.INT32: return in.readInt();
      case Tags.INT64: return in.readLong();
      case Tags.FLOAT32: return in.readFloat();
      case Tags.FLOAT64: return in.readDouble();
      case Tags.CHAR: return in.readChar();
      case Tags.STRING: return readText();
      case Tags.BYTES: return readBytes();
      case Tags.BOOLEANS: return readBooleans();
      case Tags.SHORTS: return readShorts();
      case Tags.CHARS: return readChars();
      case Tags.INTS: return readInts();
      case Tags.LONGS: return readLongs();
      case Tags.FLOATS: return readFloats();
      case Tags.DOUBLES: return readDoubles();
      case Tags.ARRAY: return readArray();
      case Tags.LIST: return readList();
      case Tags.SET: return readSet();
      case Tags.MAP: return readMap();
      case Tags.ENUM: return readEnum();
      case Tags.RECORD: return Structs.readRecord(this);
      case Tags.OBJECT: return Structs.readObject(this);
      case Tags.THROWABLE: return ThrowableCodec.read(this);
      case Tags.SERVICE_INFO: return DescriptorCodec.read(this);
      case Tags.ANNOTATION: return AnnotationCodec.read(this);
      case Tags.CLASS: return readClass();
      case Tags.BIG_INTEGER: return readBigInteger();
      case Tags.BIG_DECIMAL: return readBigDecimal();
      case Tags.UUID: return new UUID(in.readLong(), in.readLong());
      case Tags.INSTANT: return readInstant();
      case Tags.DURATION: return Duration.ofSeconds(in.readLong(), readNanos());
      case Tags.JAVA:
        if (!javaSerialization) {
          throw new MalformedValueException("a Java-serialized value at offset " + in.at(-1)
              + ", where none may be");
        }
        return JavaSerialization.read(this);
      default: throw new MalformedValueException(
          String.format("unknown tag 0x%02X at offset %d", tag, in.at(-1)));
    }
  }

  /** A varint string length (bounded by maxElements) and the UTF-8 bytes. */
  String readText() throws MalformedValueException {
    return in.readText(limits.maxElements());
  }

  /** A type, component or member name: at most 65535 bytes. */
  String readName() throws MalformedValueException {
    return in.readText(Tags.MAX_NAME_BYTES);
  }

  /** A nullable text: varint 0 for null, else the byte length plus one, then the UTF-8 bytes. */
  String readNullableText() throws MalformedValueException {
    int n = in.readVarUInt();
    if (n == 0) {
      return null;
    }
    if (n - 1 > limits.maxElements()) {
      throw new MalformedValueException(
          "text of " + (n - 1) + " bytes exceeds maxElements at offset " + in.at(0));
    }
    return in.readUtf8(n - 1);
  }

  /**
   * Reads an element count and checks it against maxElements and against the bytes left, given
   * that every element takes at least {@code minBytes}, beside the bytes that the elements still
   * to come of the containers around it need.
   */
  int readCount(int minBytes) throws MalformedValueException {
    int n = in.readVarUInt();
    if (n > limits.maxElements()) {
      throw new MalformedValueException("count " + n + " exceeds the limit of "
          + limits.maxElements() + " elements at offset " + in.at(0));
    }
    long needs = (long) n * minBytes;
    if (needs + pending > in.remaining()) {
      throw new MalformedValueException("count " + n + " at offset " + in.at(0)
          + " needs at least " + needs + " bytes"
          + (pending == 0 ? "" : " beside the " + pending + " that the rest of the values around it need")
          + ", " + in.remaining() + " left");
    }
    return n;
  }

  /**
   * {@link #readCount}, for a container whose elements are values read in turn: their bytes are
   * counted as {@link #pending} until each is read ({@link #nextElement}).
   */
  int readElements(int minBytes) throws MalformedValueException {
    int n = readCount(minBytes);
    pending += (long) n * minBytes;
    return n;
  }

  /** The next of the elements counted by {@link #readElements} is read now. */
  void nextElement(int minBytes) {
    pending -= minBytes;
  }

  /** Enters a container; fails if that nests deeper than maxDepth. */
  void enter() throws MalformedValueException {
    if (++depth > limits.maxDepth()) {
      throw new MalformedValueException(
          "values nest deeper than " + limits.maxDepth() + " levels at offset " + in.at(0));
    }
  }

  void leave() {
    depth--;
  }

  int depth() {
    return depth;
  }

  void resetDepth(int depth) {
    this.depth = depth;
  }

  /**
   * Reads a value bounded by its own length (an annotation entry): counts inside it are checked
   * against its bytes alone, and what the values around it need is taken again afterwards.
   */
  long suspendPending() {
    long p = pending;
    pending = 0;
    return p;
  }

  void resumePending(long pending) {
    this.pending = pending;
  }

  /**
   * Loads a class named in the input, checking the name's syntax and the allow-list before loading
   * it (without initialising it).
   */
  Class<?> resolve(String name) throws TRADESerializationException {
    Class<?> known = types.get(name, loader);
    if (known != null && allowList.isAllowed(name)) {
      return known;
    }
    Class<?> primitive = Types.primitive(name);
    if (primitive != null) {
      return primitive;
    }
    if (!TypeNames.isValid(name)) {
      throw new MalformedValueException("invalid type name '" + name + "'");
    }
    if (!allowList.isAllowed(name)) {
      throw refused(name);
    }
    try {
      Class<?> type = Class.forName(name, false, loader);
      types.put(name, loader, type);
      return type;
    } catch (ClassNotFoundException | LinkageError e) {
      throw new TRADESerializationException("Cannot decode a " + name
          + ": the class is not known here (" + e.getMessage() + ")");
    }
  }

  /**
   * Loads the type of an ANNOTATION value: as {@link #resolve} when the allow-list allows it;
   * otherwise, unless a refusal names it, it is loaded without initialisation and accepted if it is
   * an annotation type. Decoding an annotation runs none of its code (the instance is TRADE's
   * proxy, answering with the decoded members), so an annotation type this JVM knows is safe to
   * decode; this is what lets annotations of services travel without configuration.
   */
  Class<?> resolveAnnotationType(String name) throws TRADESerializationException {
    if (!TypeNames.isValid(name) || Types.primitive(name) != null) {
      throw new MalformedValueException("invalid annotation type name '" + name + "'");
    }
    if (allowList.isAllowed(name) || allowList.refuses(name)) {
      return resolve(name);
    }
    Class<?> type;
    try {
      type = Class.forName(name, false, loader);
    } catch (ClassNotFoundException | LinkageError e) {
      throw new TRADESerializationException("Cannot decode annotation @" + name
          + ": the class is not known here (" + e.getMessage() + ")");
    }
    if (!type.isAnnotation()) {
      throw refused(name);
    }
    return type;
  }

  static TRADESerializationException refused(String name) {
    String element = AllowList.elementName(name);
    String pkg = element == null || element.lastIndexOf('.') < 0
        ? element : element.substring(0, element.lastIndexOf('.')) + ".*";
    return new TRADESerializationException("Class " + name
        + " is not allowed to be decoded here; to allow it, add a pattern such as " + pkg
        + " to " + AllowList.CONFIG_KEY);
  }

  private List<Object> readList() throws TRADESerializationException {
    int n = readElements(1);
    enter();
    List<Object> list = new ArrayList<>(n);
    for (int i = 0; i < n; i++) {
      nextElement(1);
      list.add(readValue());
    }
    depth--;
    return list;
  }

  private Set<Object> readSet() throws TRADESerializationException {
    int n = readElements(1);
    enter();
    Set<Object> set = new LinkedHashSet<>(capacity(n));
    for (int i = 0; i < n; i++) {
      nextElement(1);
      set.add(readValue());
    }
    depth--;
    return set;
  }

  private Map<Object, Object> readMap() throws TRADESerializationException {
    int n = readElements(2);
    enter();
    Map<Object, Object> map = new LinkedHashMap<>(capacity(n));
    for (int i = 0; i < n; i++) {
      nextElement(2);
      Object key = readValue();
      map.put(key, readValue());
    }
    depth--;
    return map;
  }

  private static int capacity(int n) {
    return (int) Math.min((n * 4L) / 3 + 1, 1 << 30);
  }

  private Object readArray() throws TRADESerializationException {
    String componentName = readName();
    Class<?> component = resolve(componentName);
    if (component.isPrimitive()) {
      throw new MalformedValueException("object array of primitive type " + componentName);
    }
    if (componentName.startsWith("[".repeat(TypeNames.MAX_DIMENSIONS))) {
      throw new MalformedValueException("array of more than 255 dimensions");
    }
    int n = readElements(1);
    enter();
    Object[] array = (Object[]) Array.newInstance(component, n);
    for (int i = 0; i < n; i++) {
      nextElement(1);
      Object element = readValue();
      if (element != null && !component.isInstance(element)) {
        throw new TRADESerializationException("Cannot decode a " + componentName + "[]: element "
            + i + " is a " + element.getClass().getName());
      }
      array[i] = element;
    }
    depth--;
    return array;
  }

  private Object readEnum() throws TRADESerializationException {
    String typeName = readName();
    Class<?> type = resolve(typeName);
    String constant = readName();
    ClassModel m = ClassModel.of(type);
    if (m.constants == null) {
      throw new TRADESerializationException("Cannot decode " + typeName + "." + constant + ": "
          + (m.reason == null ? typeName + " is not an enum here" : m.reason));
    }
    Enum<?> value = m.constants.get(constant);
    if (value == null) {
      throw new TRADESerializationException(
          "Cannot decode " + typeName + "." + constant + ": no such constant here");
    }
    return value;
  }

  private Class<?> readClass() throws TRADESerializationException {
    return resolve(readName());
  }

  private BigInteger readBigInteger() throws MalformedValueException {
    int n = readCount(1);
    if (n == 0) {
      throw new MalformedValueException("big integer of zero bytes at offset " + in.at(0));
    }
    in.require(n);
    BigInteger v = new BigInteger(in.buf, in.pos, n);
    in.pos += n;
    return v;
  }

  private BigDecimal readBigDecimal() throws MalformedValueException {
    int scale = in.readInt();
    return new BigDecimal(readBigInteger(), scale);
  }

  private Instant readInstant() throws MalformedValueException {
    long seconds = in.readLong();
    try {
      return Instant.ofEpochSecond(seconds, readNanos());
    } catch (DateTimeException e) {
      throw new MalformedValueException("instant out of range: " + seconds + " s", e);
    }
  }

  private int readNanos() throws MalformedValueException {
    int nanos = in.readInt();
    if (nanos < 0 || nanos > 999_999_999) {
      throw new MalformedValueException("nanoseconds out of range: " + nanos);
    }
    return nanos;
  }

  private byte[] readBytes() throws MalformedValueException {
    byte[] a = new byte[readCount(1)];
    in.readFully(a, 0, a.length);
    return a;
  }

  private boolean[] readBooleans() throws MalformedValueException {
    boolean[] a = new boolean[readCount(1)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++) {
      int x = b[p++];
      if ((x & ~1) != 0) {
        throw new MalformedValueException("boolean byte " + x + " at offset " + in.at(i));
      }
      a[i] = x == 1;
    }
    in.pos = p;
    return a;
  }

  private short[] readShorts() throws MalformedValueException {
    short[] a = new short[readCount(2)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 2) {
      a[i] = (short) SHORTS.get(b, p);
    }
    in.pos = p;
    return a;
  }

  private char[] readChars() throws MalformedValueException {
    char[] a = new char[readCount(2)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 2) {
      a[i] = (char) (short) SHORTS.get(b, p);
    }
    in.pos = p;
    return a;
  }

  private int[] readInts() throws MalformedValueException {
    int[] a = new int[readCount(4)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 4) {
      a[i] = (int) INTS.get(b, p);
    }
    in.pos = p;
    return a;
  }

  private long[] readLongs() throws MalformedValueException {
    long[] a = new long[readCount(8)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 8) {
      a[i] = (long) LONGS.get(b, p);
    }
    in.pos = p;
    return a;
  }

  private float[] readFloats() throws MalformedValueException {
    float[] a = new float[readCount(4)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 4) {
      a[i] = Float.intBitsToFloat((int) INTS.get(b, p));
    }
    in.pos = p;
    return a;
  }

  private double[] readDoubles() throws MalformedValueException {
    double[] a = new double[readCount(8)];
    byte[] b = in.buf;
    int p = in.pos;
    for (int i = 0; i < a.length; i++, p += 8) {
      a[i] = Double.longBitsToDouble((long) LONGS.get(b, p));
    }
    in.pos = p;
    return a;
  }
}
