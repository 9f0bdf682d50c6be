package dev.trade.internal.codec;

import static dev.trade.internal.codec.ByteSink.INTS;
import static dev.trade.internal.codec.ByteSink.LONGS;
import static dev.trade.internal.codec.ByteSink.SHORTS;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * Reads big-endian numbers, varints and UTF-8 text from a byte array slice, the counterpart of
 * {@link ByteSink}. Every read is bounds-checked and fails with {@link MalformedValueException}
 * when the input ends early, so a reader never sees an unchecked exception on short input.
 *
 * <p>{@link #position()} counts from the start of the slice. After a failed read the position is
 * unspecified.
 *
 * <p>Not thread-safe: one source belongs to one reader at a time.
 */
public final class ByteSource {
  final byte[] buf;
  private final int start;
  /** The real end of the input. */
  private final int end;
  /** Where reading must stop; below {@link #end} while a bounded value is being read. */
  int limit;

  int pos;

  private ByteSource(byte[] buf, int start, int end) {
    this.buf = buf;
    this.start = start;
    this.end = end;
    this.limit = end;
    this.pos = start;
  }

  /** Reads all of {@code data}, which is not copied. */
  public static ByteSource of(byte[] data) {
    return new ByteSource(data, 0, data.length);
  }

  /**
   * Reads {@code data[offset .. offset+length)}, which is not copied.
   *
   * @throws IndexOutOfBoundsException if the slice is not inside {@code data}
   */
  public static ByteSource of(byte[] data, int offset, int length) {
    Objects.checkFromIndexSize(offset, length, data.length);
    return new ByteSource(data, offset, offset + length);
  }

  /**
   * Reads the remaining bytes of {@code buffer}, sharing its array when it has an accessible one and
   * copying them otherwise. The buffer's own position is not changed.
   */
  public static ByteSource of(ByteBuffer buffer) {
    if (buffer.hasArray()) {
      int offset = buffer.arrayOffset() + buffer.position();
      return new ByteSource(buffer.array(), offset, offset + buffer.remaining());
    }
    byte[] copy = new byte[buffer.remaining()];
    buffer.duplicate().get(copy);
    return of(copy);
  }

  /** The number of bytes read so far from the start of the slice. */
  public int position() {
    return pos - start;
  }

  /** The number of bytes left to read. */
  public int remaining() {
    return limit - pos;
  }

  /** Skips {@code n} bytes. */
  public void skip(int n) throws MalformedValueException {
    require(n);
    pos += n;
  }

  /** Reads one signed byte. */
  public byte readByte() throws MalformedValueException {
    if (pos >= limit) {
      throw underflow(1);
    }
    return buf[pos++];
  }

  /** Reads one byte as a value in {@code 0..255}. */
  public int readUnsignedByte() throws MalformedValueException {
    if (pos >= limit) {
      throw underflow(1);
    }
    return buf[pos++] & 0xFF;
  }

  /** Reads a big-endian 16-bit signed integer. */
  public short readShort() throws MalformedValueException {
    require(2);
    short v = (short) SHORTS.get(buf, pos);
    pos += 2;
    return v;
  }

  /** Reads a big-endian 16-bit UTF-16 code unit. */
  public char readChar() throws MalformedValueException {
    return (char) readShort();
  }

  /** Reads a big-endian 32-bit signed integer. */
  public int readInt() throws MalformedValueException {
    require(4);
    int v = (int) INTS.get(buf, pos);
    pos += 4;
    return v;
  }

  /** Reads a big-endian 64-bit signed integer. */
  public long readLong() throws MalformedValueException {
    require(8);
    long v = (long) LONGS.get(buf, pos);
    pos += 8;
    return v;
  }

  /** Reads a big-endian IEEE 754 single. */
  public float readFloat() throws MalformedValueException {
    return Float.intBitsToFloat(readInt());
  }

  /** Reads a big-endian IEEE 754 double. */
  public double readDouble() throws MalformedValueException {
    return Double.longBitsToDouble(readLong());
  }

  /**
   * Reads an unsigned LEB128 varint in {@code 0 .. 2^31-1}, as {@link ByteSink#writeVarUInt} writes
   * it. Longer than 5 bytes, larger than {@code 2^31-1} or not in shortest form is malformed.
   */
  public int readVarUInt() throws MalformedValueException {
    if (pos >= limit) {
      throw underflow(1);
    }
    int b = buf[pos++];
    if (b >= 0) {
      return b;
    }
    int result = b & 0x7F;
    for (int shift = 7; shift <= 28; shift += 7) {
      if (pos >= limit) {
        throw underflow(1);
      }
      b = buf[pos++];
      result |= (b & 0x7F) << shift;
      if (b >= 0) {
        if (b == 0) {
          throw new MalformedValueException("varint not in shortest form at offset " + at(-1));
        }
        if (shift == 28 && b > 0x07) {
          throw new MalformedValueException("varint exceeds 2^31-1 at offset " + at(-1));
        }
        return result;
      }
    }
    throw new MalformedValueException("varint longer than 5 bytes at offset " + at(-1));
  }

  /** Reads exactly {@code length} bytes into {@code dst[offset ..]}. */
  public void readFully(byte[] dst, int offset, int length) throws MalformedValueException {
    require(length);
    System.arraycopy(buf, pos, dst, offset, length);
    pos += length;
  }

  /**
   * Reads a varint byte length and that many bytes of UTF-8, as {@link ByteSink#writeText} writes
   * them.
   *
   * @param maxBytes the longest text accepted, in bytes
   */
  public String readText(int maxBytes) throws MalformedValueException {
    int length = readVarUInt();
    if (length > maxBytes) {
      throw new MalformedValueException(
          "text of " + length + " bytes exceeds " + maxBytes + " at offset " + at(0));
    }
    return readUtf8(length);
  }

  /** Reads {@code length} bytes of strict UTF-8: no overlong forms, surrogates or bad sequences. */
  String readUtf8(int length) throws MalformedValueException {
    require(length);
    byte[] b = buf;
    int p = pos;
    int stop = p + length;
    while (p < stop && b[p] >= 0) {
      p++;
    }
    if (p == stop) { // all ASCII, the common case: the JDK copies Latin-1 into a compact string
      String s = new String(b, pos, length, StandardCharsets.ISO_8859_1);
      pos = stop;
      return s;
    }
    char[] chars = new char[length];
    int n = 0;
    for (p = pos; p < stop; ) {
      int b0 = b[p] & 0xFF;
      if (b0 < 0x80) {
        chars[n++] = (char) b0;
        p++;
      } else if (b0 >= 0xC2 && b0 <= 0xDF && p + 1 < stop && isCont(b[p + 1])) {
        chars[n++] = (char) (((b0 & 0x1F) << 6) | (b[p + 1] & 0x3F));
        p += 2;
      } else if (b0 >= 0xE0 && b0 <= 0xEF && p + 2 < stop && isCont(b[p + 1]) && isCont(b[p + 2])) {
        int cp = ((b0 & 0x0F) << 12) | ((b[p + 1] & 0x3F) << 6) | (b[p + 2] & 0x3F);
        if (cp < 0x800 || Character.isSurrogate((char) cp)) {
          throw badUtf8(p);
        }
        chars[n++] = (char) cp;
        p += 3;
      } else if (b0 >= 0xF0 && b0 <= 0xF4 && p + 3 < stop
          && isCont(b[p + 1]) && isCont(b[p + 2]) && isCont(b[p + 3])) {
        int cp = ((b0 & 0x07) << 18) | ((b[p + 1] & 0x3F) << 12)
            | ((b[p + 2] & 0x3F) << 6) | (b[p + 3] & 0x3F);
        if (cp < 0x10000 || cp > Character.MAX_CODE_POINT) {
          throw badUtf8(p);
        }
        chars[n++] = Character.highSurrogate(cp);
        chars[n++] = Character.lowSurrogate(cp);
        p += 4;
      } else {
        throw badUtf8(p);
      }
    }
    pos = stop;
    return new String(chars, 0, n);
  }

  private static boolean isCont(byte b) {
    return (b & 0xC0) == 0x80;
  }

  private MalformedValueException badUtf8(int p) {
    return new MalformedValueException("invalid UTF-8 at offset " + (p - start));
  }

  /** Fails unless {@code n} more bytes can be read. */
  void require(int n) throws MalformedValueException {
    if (n < 0 || n > limit - pos) {
      throw underflow(n);
    }
  }

  private MalformedValueException underflow(int n) {
    String what = pos + (long) n > end ? "input truncated" : "value longer than its size limit";
    return new MalformedValueException(
        what + ": " + n + " bytes needed at offset " + at(0) + ", " + (limit - pos) + " left");
  }

  /** The offset of {@code pos + delta} from the start of the slice, for messages. */
  int at(int delta) {
    return pos + delta - start;
  }

  @Override
  public String toString() {
    return "ByteSource[position=" + position() + ", remaining=" + remaining() + "]";
  }
}
