package dev.trade.internal.codec;

import dev.trade.TRADESerializationException;
import java.util.Objects;
import java.util.Set;

/**
 * Turns Java values into wire format version 1 and back: tagged, big-endian, language-neutral, as
 * specified byte by byte in {@code docs/protocol.md}. It serves remote calls (frames embed encoded
 * values) and strict-mode local calls ({@link #copy}), so that arguments and results behave alike
 * whether the service is local or remote.
 *
 * <p>Encodable values: null, booleans, the integer and floating-point types, {@code Character},
 * strings, primitive arrays, object arrays (typed: a {@code String[]} comes back as one), lists,
 * sets and maps (decoded as {@code ArrayList}, {@code LinkedHashSet} and {@code LinkedHashMap}),
 * enums, records, plain data classes, exceptions, annotations, {@code Class} objects, service infos
 * (through {@link InfoBinding}), {@code BigInteger}, {@code BigDecimal}, {@code UUID},
 * {@code Instant} and {@code Duration}. Any other class travels with Java serialization if it is
 * {@code Serializable}. Decoded numbers keep their Java type ({@code int32} is an {@code Integer}).
 *
 * <p>Decoding is safe for hostile input: every class named in the input must pass the
 * {@link AllowList} before it is loaded, and every length, count and nesting level is checked
 * against {@link Limits} before anything is allocated. Bytes that are not a valid value fail with
 * {@link MalformedValueException}; a well-formed value that names a refused, unknown or
 * incompatible class fails with its superclass, {@link TRADESerializationException}.
 *
 * <p>Records and data classes are read and rebuilt reflectively. On the module path, their packages
 * must therefore be open to module {@code dev.trade}; a class whose members cannot be made
 * accessible travels with Java serialization if it is {@code Serializable}, and fails otherwise.
 *
 * <p>Instances are immutable and safe for concurrent use; per-class reflection is done once and
 * cached. The allow-list is shared, so patterns added to it later apply to this codec.
 */
public final class Codec {
  private final AllowList allowList;
  private final Limits limits;
  private final InfoBinding info;
  private final boolean javaSerialization;
  private final TypeCache types = new TypeCache();

  /**
   * A codec for values of every kind, Java-serialized ones included.
   *
   * @param allowList the classes decoding may load
   * @param limits the bounds on one encoded value
   * @param info how service infos are described and bound; {@link InfoBinding#NONE} if none travel
   */
  public Codec(AllowList allowList, Limits limits, InfoBinding info) {
    this(allowList, limits, info, true);
  }

  /**
   * @param javaSerialization whether a JAVA value is decoded; false for what never holds one
   *     (service tables hold descriptors only), so that no Java stream, whose cost the filter
   *     cannot bound (nested hash sets: exponential hashing), is ever read there
   */
  public Codec(AllowList allowList, Limits limits, InfoBinding info, boolean javaSerialization) {
    this.allowList = Objects.requireNonNull(allowList, "allowList == null");
    this.limits = Objects.requireNonNull(limits, "limits == null");
    this.info = Objects.requireNonNull(info, "info == null");
    this.javaSerialization = javaSerialization;
  }

  public AllowList allowList() {
    return allowList;
  }

  public Limits limits() {
    return limits;
  }

  /**
   * Appends the encoding of {@code value} to {@code out}. On failure {@code out} is left as it was.
   *
   * @throws TRADESerializationException if the value or something it holds cannot be encoded (the
   *     message names the class and where it sits), nests deeper than {@code maxDepth} (usually a
   *     cycle), or needs more than {@code maxBytes}
   */
  public void write(Object value, ByteSink out) throws TRADESerializationException {
    Objects.requireNonNull(out, "out == null");
    int start = out.size();
    try {
      Encoder encoder = new Encoder(out, limits, info);
      encoder.writeValue(value);
      encoder.checkRoom(0);
    } catch (TRADESerializationException e) {
      out.truncate(start);
      throw e;
    } catch (RuntimeException e) { // thrown by the value's own methods (iterators, accessors)
      out.truncate(start);
      throw new TRADESerializationException("Cannot encode a "
          + (value == null ? "null" : value.getClass().getName()) + ": " + e, e);
    }
  }

  /**
   * Reads one value from {@code in}, which is left positioned after it. Trailing bytes are not
   * examined. After a failure the position of {@code in} is unspecified.
   *
   * @param loader the class loader in which the type names of the value are resolved
   * @throws MalformedValueException if the bytes are not a valid value within the limits
   * @throws TRADESerializationException if the value names a class that is not allowed (the message
   *     names the class and {@value AllowList#CONFIG_KEY}), not known to {@code loader}, or that does
   *     not accept the decoded values
   */
  public Object read(ByteSource in, ClassLoader loader) throws TRADESerializationException {
    return read(in, loader, Set.of());
  }

  /**
   * As {@link #read(ByteSource, ClassLoader)}, also allowing the classes named in
   * {@code declared} (binary names; see {@link AllowList#with}): those a service's signature
   * declares, for its calls and replies.
   */
  public Object read(ByteSource in, ClassLoader loader, Set<String> declared)
      throws TRADESerializationException {
    Objects.requireNonNull(in, "in == null");
    Objects.requireNonNull(loader, "loader == null");
    int savedLimit = in.limit;
    long valueLimit = (long) in.pos + limits.maxBytes();
    if (valueLimit < savedLimit) {
      in.limit = (int) valueLimit;
    }
    try {
      return new Decoder(in, limits, allowList.with(declared), info, loader, types,
          javaSerialization).readValue();
    } catch (RuntimeException e) { // a safety net; the decoder checks everything it knows of
      throw new MalformedValueException("internal decoding error: " + e, e);
    } finally {
      in.limit = savedLimit;
    }
  }

  /**
   * The encoding of {@code value} as a new array.
   *
   * @throws TRADESerializationException as {@link #write}
   */
  public byte[] encode(Object value) throws TRADESerializationException {
    ByteSink sink = new ByteSink(64);
    write(value, sink);
    return sink.toByteArray();
  }

  /**
   * Decodes a value that fills all of {@code data}.
   *
   * @throws MalformedValueException also if bytes follow the value
   * @throws TRADESerializationException as {@link #read}
   */
  public Object decode(byte[] data, ClassLoader loader) throws TRADESerializationException {
    ByteSource in = ByteSource.of(data);
    Object value = read(in, loader);
    if (in.remaining() != 0) {
      throw new MalformedValueException(
          in.remaining() + " bytes follow the value at offset " + in.position());
    }
    return value;
  }

  /**
   * A copy of {@code value} with the semantics of a remote call, for strict-mode local calls.
   * Immutable values are returned as they are: null, strings, boxed primitives, enums, service
   * infos, {@code BigInteger}, {@code BigDecimal}, {@code UUID}, {@code Instant}, {@code Duration},
   * {@code Class} objects, annotations, and records whose components are all immutable by this
   * rule. Anything else is encoded and decoded, with type names resolved in {@code loader}.
   *
   * @throws TRADESerializationException if the value cannot be encoded, or decoded in
   *     {@code loader} (for example a class the allow-list refuses)
   */
  public Object copy(Object value, ClassLoader loader) throws TRADESerializationException {
    return copy(value, loader, Set.of());
  }

  /** As {@link #copy(Object, ClassLoader)}, decoding as {@link #read(ByteSource, ClassLoader, Set)}. */
  public Object copy(Object value, ClassLoader loader, Set<String> declared)
      throws TRADESerializationException {
    if (isImmutable(value, 0)) {
      return value;
    }
    ByteSink sink = new ByteSink(64);
    write(value, sink);
    return read(ByteSource.of(sink.array(), 0, sink.size()), loader, declared);
  }

  private boolean isImmutable(Object value, int depth) {
    if (value == null) {
      return true;
    }
    ClassModel m = ClassModel.of(value.getClass());
    switch (m.kind) {
      case STRING, BOOLEAN, BYTE, SHORT, INT, LONG, FLOAT, DOUBLE, CHAR,
          BIG_INTEGER, BIG_DECIMAL, UUID, INSTANT, DURATION, CLASS, ENUM, ANNOTATION:
        return true;
      case RECORD:
        if (info.describe(value) != null) {
          return true;
        }
        if (depth >= limits.maxDepth()) {
          return false;
        }
        for (int i = 0; i < m.getters.length; i++) {
          try {
            if (!isImmutable((Object) m.getters[i].invokeExact(value), depth + 1)) {
              return false;
            }
          } catch (Error e) {
            throw e;
          } catch (Throwable e) {
            return false; // let the encoder report the failing accessor
          }
        }
        return true;
      case DATA, SERIALIZABLE, UNSUPPORTED:
        return info.describe(value) != null;
      default:
        return false;
    }
  }

  @Override
  public String toString() {
    return "Codec[" + limits + ", " + allowList + "]";
  }
}
