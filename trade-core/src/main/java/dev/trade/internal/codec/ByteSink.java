package dev.trade.internal.codec;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.Arrays;

/**
 * A growable output buffer that writes numbers big-endian, lengths as unsigned LEB128 varints and
 * strings as length-prefixed UTF-8, exactly as {@code docs/protocol.md} specifies them.
 *
 * <p>The valid bytes are {@code array()[0 .. size())}. A sink is reused by calling {@link #reset()};
 * frames are built by writing a header, then values through {@link Codec#write}, then patching the
 * header with {@link #putInt}.
 *
 * <p>Not thread-safe: one sink belongs to one writer at a time.
 */
public final class ByteSink {
  static final VarHandle SHORTS =
      MethodHandles.byteArrayViewVarHandle(short[].class, ByteOrder.BIG_ENDIAN);
  static final VarHandle INTS =
      MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
  static final VarHandle LONGS =
      MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

  /** The largest array the JVM reliably allocates. */
  static final int MAX_CAPACITY = Integer.MAX_VALUE - 8;

  byte[] buf;
  int size;

  /** A sink with room for 256 bytes before it first grows. */
  public ByteSink() {
    this(256);
  }

  /** @throws IllegalArgumentException if {@code initialCapacity} is negative */
  public ByteSink(int initialCapacity) {
    if (initialCapacity < 0) {
      throw new IllegalArgumentException("initialCapacity < 0: " + initialCapacity);
    }
    buf = new byte[initialCapacity];
  }

  /** The number of bytes written since creation or the last {@link #reset()}. */
  public int size() {
    return size;
  }

  /**
   * The backing array, valid up to {@link #size()}. It is replaced when the sink grows, so do not
   * keep it across writes.
   */
  public byte[] array() {
    return buf;
  }

  /** Forgets the written bytes and keeps the backing array for reuse. */
  public void reset() {
    size = 0;
  }

  /** A copy of the written bytes. */
  public byte[] toByteArray() {
    return Arrays.copyOf(buf, size);
  }

  /** Drops the bytes after {@code newSize}; used to undo a failed write. */
  void truncate(int newSize) {
    size = newSize;
  }

  /**
   * Makes room for {@code extra} more bytes.
   *
   * @throws IllegalStateException if the sink would exceed about 2 GiB
   */
  public void ensureCapacity(int extra) {
    if (extra > buf.length - size) {
      grow(extra);
    }
  }

  private void grow(int extra) {
    long needed = (long) size + extra;
    if (extra < 0 || needed > MAX_CAPACITY) {
      throw new IllegalStateException("ByteSink cannot hold " + needed + " bytes");
    }
    long doubled = Math.max(2L * buf.length, 64);
    buf = Arrays.copyOf(buf, (int) Math.min(MAX_CAPACITY, Math.max(needed, doubled)));
  }

  /** Writes the low 8 bits of {@code v}. */
  public void writeByte(int v) {
    if (size == buf.length) {
      grow(1);
    }
    buf[size++] = (byte) v;
  }

  /** Writes the low 16 bits of {@code v}, big-endian. */
  public void writeShort(int v) {
    ensureCapacity(2);
    SHORTS.set(buf, size, (short) v);
    size += 2;
  }

  /** Writes a 32-bit int, big-endian. */
  public void writeInt(int v) {
    ensureCapacity(4);
    INTS.set(buf, size, v);
    size += 4;
  }

  /** Writes a 64-bit long, big-endian. */
  public void writeLong(long v) {
    ensureCapacity(8);
    LONGS.set(buf, size, v);
    size += 8;
  }

  /** Writes the IEEE 754 bits of {@code v} (NaN payloads are kept), big-endian. */
  public void writeFloat(float v) {
    writeInt(Float.floatToRawIntBits(v));
  }

  /** Writes the IEEE 754 bits of {@code v} (NaN payloads are kept), big-endian. */
  public void writeDouble(double v) {
    writeLong(Double.doubleToRawLongBits(v));
  }

  /**
   * Writes {@code v} as an unsigned LEB128 varint in its shortest form: 7 bits per byte, least
   * significant group first, high bit set on every byte but the last; 1 to 5 bytes.
   *
   * @throws IllegalArgumentException if {@code v} is negative
   */
  public void writeVarUInt(int v) {
    if (v < 0) {
      throw new IllegalArgumentException("negative varint: " + v);
    }
    ensureCapacity(5);
    byte[] b = buf;
    int p = size;
    while (v >= 0x80) {
      b[p++] = (byte) (v | 0x80);
      v >>>= 7;
    }
    b[p++] = (byte) v;
    size = p;
  }

  /** Writes all of {@code bytes}. */
  public void writeBytes(byte[] bytes) {
    writeBytes(bytes, 0, bytes.length);
  }

  /** Writes {@code bytes[offset .. offset+length)}. */
  public void writeBytes(byte[] bytes, int offset, int length) {
    ensureCapacity(length);
    System.arraycopy(bytes, offset, buf, size, length);
    size += length;
  }

  /**
   * Overwrites four already written bytes at {@code position} with {@code v}, big-endian: for
   * length fields that are known only after their content was written.
   *
   * @throws IndexOutOfBoundsException unless {@code 0 <= position <= size() - 4}
   */
  public void putInt(int position, int v) {
    if (position < 0 || position > size - 4) {
      throw new IndexOutOfBoundsException("position " + position + ", size " + size);
    }
    INTS.set(buf, position, v);
  }

  /**
   * Writes {@code s} as a varint byte length followed by its UTF-8 bytes. An unpaired surrogate,
   * which UTF-8 cannot represent, is written as U+FFFD.
   */
  public void writeText(String s) {
    int n = s.length();
    if (n <= 42) { // at most 126 UTF-8 bytes: the length fits in one varint byte, patched after
      ensureCapacity(1 + 3 * n);
      int lengthAt = size++;
      int p = encodeUtf8(s, n, buf, size);
      buf[lengthAt] = (byte) (p - size);
      size = p;
    } else {
      int length = utf8Length(s, n);
      writeVarUInt(length);
      ensureCapacity(length);
      size = encodeUtf8(s, n, buf, size);
    }
  }

  /**
   * Writes a text that may be null: varint 0 for null, otherwise the UTF-8 byte length plus one,
   * then the bytes.
   */
  void writeNullableText(String s) {
    if (s == null) {
      writeByte(0);
      return;
    }
    int n = s.length();
    int length = utf8Length(s, n);
    if (length == Integer.MAX_VALUE) {
      throw new IllegalStateException("string too long for UTF-8: " + length + " bytes");
    }
    writeVarUInt(length + 1);
    ensureCapacity(length);
    size = encodeUtf8(s, n, buf, size);
  }

  /** The number of bytes {@link #writeText} uses for the characters of {@code s}. */
  static int utf8Length(String s, int n) {
    long length = n;
    for (int i = 0; i < n; i++) {
      char c = s.charAt(i);
      if (c >= 0x80) {
        if (c < 0x800) {
          length += 1;
        } else if (Character.isHighSurrogate(c)
            && i + 1 < n
            && Character.isLowSurrogate(s.charAt(i + 1))) {
          length += 2; // two chars, four bytes
          i++;
        } else {
          length += 2; // three bytes, also for an unpaired surrogate written as U+FFFD
        }
      }
    }
    if (length > MAX_CAPACITY) {
      throw new IllegalStateException("string too long for UTF-8: " + length + " bytes");
    }
    return (int) length;
  }

  private static int encodeUtf8(String s, int n, byte[] b, int p) {
    for (int i = 0; i < n; i++) {
      char c = s.charAt(i);
      if (c < 0x80) {
        b[p++] = (byte) c;
      } else if (c < 0x800) {
        b[p++] = (byte) (0xC0 | (c >> 6));
        b[p++] = (byte) (0x80 | (c & 0x3F));
      } else if (Character.isSurrogate(c)) {
        int cp = 0xFFFD;
        if (Character.isHighSurrogate(c) && i + 1 < n && Character.isLowSurrogate(s.charAt(i + 1))) {
          cp = Character.toCodePoint(c, s.charAt(++i));
        }
        if (cp == 0xFFFD) {
          b[p++] = (byte) 0xEF;
          b[p++] = (byte) 0xBF;
          b[p++] = (byte) 0xBD;
        } else {
          b[p++] = (byte) (0xF0 | (cp >> 18));
          b[p++] = (byte) (0x80 | ((cp >> 12) & 0x3F));
          b[p++] = (byte) (0x80 | ((cp >> 6) & 0x3F));
          b[p++] = (byte) (0x80 | (cp & 0x3F));
        }
      } else {
        b[p++] = (byte) (0xE0 | (c >> 12));
        b[p++] = (byte) (0x80 | ((c >> 6) & 0x3F));
        b[p++] = (byte) (0x80 | (c & 0x3F));
      }
    }
    return p;
  }

  @Override
  public String toString() {
    return "ByteSink[size=" + size + ", capacity=" + buf.length + "]";
  }
}
