package dev.trade.internal.codec;

import dev.trade.internal.registry.Types;
import dev.trade.TRADESerializationException;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.InvalidClassException;
import java.io.NotSerializableException;
import java.io.ObjectInputFilter;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.ObjectStreamClass;

/**
 * The last resort for classes the structural encoding cannot take: standard Java serialization,
 * decoded only behind an allow-list filter that rejects every class no pattern allows, plus depth,
 * reference, array-length and byte limits (JEP 290). Dynamic proxies are always refused.
 *
 * <p>Its depth is bounded far tighter than a structural value's ({@link #MAX_DEPTH}): allowed
 * classes such as {@code HashSet} compute hash codes while they read, and sets nested in sets,
 * each holding the next level twice, cost about twice as much per level (a 1.2 KB value 20 levels
 * deep took 0.45 s of a core, 22 levels 1.4 s, and a 2.9 KB one 50 levels deep more than a call's
 * deadline). No filter can stop such work once it runs, so the bound must keep it small.
 */
final class JavaSerialization {
  /**
   * The deepest a Java-serialized value may nest (the filter's depth: each object read inside
   * another is one level deeper): 16 levels, at which the nested-set value above takes about 2 ms.
   * A deeper graph is refused with an error that says so; a record or a data class takes the
   * structural encoding, which nests up to {@code Limits.maxDepth}.
   */
  static final int MAX_DEPTH = 16;

  private JavaSerialization() {}

  static void write(Encoder e, Object value) throws TRADESerializationException {
    String name = value.getClass().getName();
    Bytes bytes = new Bytes();
    try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
      out.writeObject(value);
    } catch (NotSerializableException ex) {
      throw new TRADESerializationException("Cannot encode " + name + ": it holds a "
          + ex.getMessage() + ", which is not Serializable", ex);
    } catch (IOException | RuntimeException | StackOverflowError ex) {
      throw new TRADESerializationException(
          "Cannot encode " + name + " with Java serialization: " + ex, ex);
    }
    e.checkCount(bytes.size(), value);
    e.checkRoom(bytes.size() + 6L);
    ByteSink out = e.out;
    out.writeByte(Tags.JAVA);
    out.writeVarUInt(bytes.size());
    out.writeBytes(bytes.array(), 0, bytes.size());
  }

  static Object read(Decoder d) throws TRADESerializationException {
    ByteSource in = d.in;
    int length = d.readCount(1);
    int offset = in.pos;
    in.pos += length;
    FilteredInput stream;
    try {
      stream = new FilteredInput(new ByteArrayInputStream(in.buf, offset, length), d, length);
    } catch (IOException e) {
      throw new MalformedValueException("bad Java serialization header: " + e, e);
    }
    try (stream) {
      return stream.readObject();
    } catch (InvalidClassException e) {
      if (stream.proxy != null) {
        throw new TRADESerializationException("Cannot decode a Java-serialized dynamic proxy of "
            + stream.proxy + ": proxies are never accepted", e);
      }
      if (stream.refused != null) {
        throw Decoder.refused(stream.refused);
      }
      if (stream.overLimit != null) {
        throw new MalformedValueException("Java-serialized value exceeds " + stream.overLimit, e);
      }
      throw new TRADESerializationException(
          "Cannot decode a " + e.classname + ": " + e.getMessage(), e);
    } catch (ClassNotFoundException e) {
      throw new TRADESerializationException(
          "Cannot decode a Java-serialized value: class not known here: " + e.getMessage(), e);
    } catch (IOException | RuntimeException e) {
      // RuntimeException: hostile streams make readObject methods of allowed classes fail
      throw new MalformedValueException("bad Java serialization stream: " + e, e);
    }
  }

  /** Resolves classes through the decoder's loader, and only after the allow-list agreed. */
  private static final class FilteredInput extends ObjectInputStream {
    private final Decoder decoder;
    private final int length;
    private final ObjectInputFilter allowed;
    String refused;
    String proxy;
    String overLimit;

    FilteredInput(InputStream bytes, Decoder decoder, int length) throws IOException {
      super(bytes);
      this.decoder = decoder;
      this.length = length;
      this.allowed = decoder.allowList.filter();
      setObjectInputFilter(this::check);
    }

    private ObjectInputFilter.Status check(ObjectInputFilter.FilterInfo info) {
      Limits limits = decoder.limits;
      int maxDepth = Math.min(limits.maxDepth(), MAX_DEPTH);
      if (info.depth() > maxDepth) {
        overLimit = "the depth of " + maxDepth + " levels that Java serialization may nest (make "
            + "the classes records or data classes to nest deeper)";
      } else if (info.references() > limits.maxElements()) {
        overLimit = "maxElements " + limits.maxElements() + " references";
      } else if (info.arrayLength() > limits.maxElements()) {
        overLimit = "maxElements " + limits.maxElements() + " array elements";
      } else if (info.arrayLength() > Math.max(0, length - info.streamBytes())) {
        // Every element takes at least a byte of the stream; the JDK allocates the array as soon
        // as this check passes, so a few bytes claiming a huge array must not pass it.
        overLimit = "its length: an array of " + info.arrayLength() + " elements in "
            + Math.max(0, length - info.streamBytes()) + " bytes left";
      } else if (info.streamBytes() > length) {
        overLimit = "its length";
      }
      if (overLimit != null) {
        return ObjectInputFilter.Status.REJECTED;
      }
      ObjectInputFilter.Status status = allowed.checkInput(info);
      if (status == ObjectInputFilter.Status.REJECTED && refused == null) {
        refused = info.serialClass().getName();
      }
      return status == ObjectInputFilter.Status.UNDECIDED ? ObjectInputFilter.Status.ALLOWED : status;
    }

    @Override
    protected Class<?> resolveClass(ObjectStreamClass desc) throws IOException, ClassNotFoundException {
      String name = desc.getName();
      Class<?> primitive = Types.primitive(name);
      if (primitive != null) {
        return primitive;
      }
      if (!decoder.allowList.isAllowed(name)) { // refuse before loading anything
        refused = name;
        throw new InvalidClassException(name, "not allowed");
      }
      try {
        return Class.forName(name, false, decoder.loader);
      } catch (LinkageError e) {
        throw new ClassNotFoundException(name, e);
      }
    }

    @Override
    protected Class<?> resolveProxyClass(String[] interfaces) throws IOException {
      proxy = String.join(", ", interfaces);
      throw new InvalidClassException("dynamic proxies are not accepted");
    }
  }

  /** Exposes its buffer so that the bytes are copied into the sink only once. */
  private static final class Bytes extends ByteArrayOutputStream {
    byte[] array() {
      return buf;
    }
  }
}
