package dev.trade.internal.codec;

/**
 * Bounds that a decoder enforces on one value before it allocates anything, so that hostile or
 * corrupt input fails with {@link MalformedValueException} instead of exhausting memory or stack.
 * The encoder applies the same bounds, so that a value that cannot be decoded is refused when it is
 * written.
 *
 * <p>Immutable, like every record. Note that the decoded object graph may need several times {@code maxBytes} of heap: a one-byte
 * {@code null} element still costs a reference, and a two-byte empty list costs an {@code ArrayList}.
 *
 * @param maxBytes the most bytes one encoded value may occupy
 * @param maxDepth the deepest nesting of containers (collections, arrays, maps, records, objects,
 *     exceptions and their causes, annotations) in one value; at most {@value #MAX_DEPTH}
 * @param maxElements the most elements of one collection, array or map, and the most bytes of one
 *     string or big number
 * @param maxStackFrames the most stack trace elements of one exception; the encoder drops the frames
 *     beyond it
 */
public record Limits(int maxBytes, int maxDepth, int maxElements, int maxStackFrames) {

  /** The largest accepted {@code maxDepth}: deeper nesting would risk the decoding thread's stack. */
  public static final int MAX_DEPTH = 512;

  /** 64 MiB per value, depth 64, 64 Mi elements (so in practice bounded by bytes), 1024 frames. */
  public static final Limits DEFAULT = new Limits(64 << 20, 64, 64 << 20, 1024);

  /**
   * @throws IllegalArgumentException if a bound is out of range: {@code maxBytes < 16},
   *     {@code maxDepth} outside {@code 1..MAX_DEPTH}, or a negative {@code maxElements} or
   *     {@code maxStackFrames}
   */
  public Limits {
    if (maxBytes < 16) {
      throw new IllegalArgumentException("maxBytes < 16: " + maxBytes);
    }
    if (maxDepth < 1 || maxDepth > MAX_DEPTH) {
      throw new IllegalArgumentException("maxDepth not in 1.." + MAX_DEPTH + ": " + maxDepth);
    }
    if (maxElements < 0) {
      throw new IllegalArgumentException("maxElements < 0: " + maxElements);
    }
    if (maxStackFrames < 0) {
      throw new IllegalArgumentException("maxStackFrames < 0: " + maxStackFrames);
    }
  }
}
