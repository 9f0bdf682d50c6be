package dev.trade.internal.codec;

import dev.trade.internal.registry.Types;

/**
 * Checks that an annotation entry a receiver skips is well-formed without loading a class: an
 * ANNOTATION value whose members hold only what an annotation member can hold
 * ({@code docs/protocol.md}, "Skipping annotation entries"). A skipped entry is otherwise never
 * read, so malformed bytes in it would pass unseen, which the spec forbids.
 */
final class AnnotationShape {
  private AnnotationShape() {}

  /** Reads one ANNOTATION value, tag included; fails if it is not well-formed. */
  static void check(Decoder d) throws MalformedValueException {
    int tag = d.in.readUnsignedByte();
    if (tag != Tags.ANNOTATION) {
      throw new MalformedValueException(
          String.format("annotation entry holds tag 0x%02X at offset %d", tag, d.in.at(-1)));
    }
    annotation(d);
  }

  private static void annotation(Decoder d) throws MalformedValueException {
    typeName(d);
    int n = d.readCount(2);
    d.enter();
    for (int i = 0; i < n; i++) {
      d.readName();
      member(d, true);
    }
    d.leave();
  }

  /** One member value; {@code arrays} is false for an element of an ARRAY (no nested arrays). */
  private static void member(Decoder d, boolean arrays) throws MalformedValueException {
    ByteSource in = d.in;
    int tag = in.readUnsignedByte();
    switch (tag) {
      case Tags.FALSE, Tags.TRUE -> { }
      case Tags.INT8 -> in.skip(1);
      case Tags.INT16, Tags.CHAR -> in.skip(2);
      case Tags.INT32, Tags.FLOAT32 -> in.skip(4);
      case Tags.INT64, Tags.FLOAT64 -> in.skip(8);
      case Tags.STRING -> d.readText();
      case Tags.CLASS -> className(d);
      case Tags.ENUM -> {
        typeName(d);
        d.readName();
      }
      case Tags.ANNOTATION -> annotation(d);
      default -> {
        if (!arrays) {
          throw notAMember(tag, in);
        }
        array(d, tag);
      }
    }
  }

  private static void array(Decoder d, int tag) throws MalformedValueException {
    ByteSource in = d.in;
    switch (tag) {
      case Tags.BYTES -> in.skip(d.readCount(1));
      case Tags.BOOLEANS -> {
        for (int i = d.readCount(1); i > 0; i--) {
          int b = in.readUnsignedByte();
          if (b > 1) {
            throw new MalformedValueException("boolean byte " + b + " at offset " + in.at(-1));
          }
        }
      }
      case Tags.SHORTS, Tags.CHARS -> in.skip(2 * d.readCount(2));
      case Tags.INTS, Tags.FLOATS -> in.skip(4 * d.readCount(4));
      case Tags.LONGS, Tags.DOUBLES -> in.skip(8 * d.readCount(8));
      case Tags.ARRAY -> {
        typeName(d);
        int n = d.readCount(1);
        d.enter();
        for (int i = 0; i < n; i++) {
          member(d, false);
        }
        d.leave();
      }
      default -> throw notAMember(tag, in);
    }
  }

  /** The name of an annotation, enum or array component type: a class, not a primitive. */
  private static void typeName(Decoder d) throws MalformedValueException {
    String name = d.readName();
    if (!TypeNames.isValid(name) || Types.primitive(name) != null) {
      throw new MalformedValueException("invalid type name '" + name + "' in an annotation entry");
    }
  }

  private static void className(Decoder d) throws MalformedValueException {
    String name = d.readName();
    if (Types.primitive(name) == null && !TypeNames.isValid(name)) {
      throw new MalformedValueException("invalid class name '" + name + "' in an annotation entry");
    }
  }

  private static MalformedValueException notAMember(int tag, ByteSource in) {
    return new MalformedValueException(String.format(
        "tag 0x%02X at offset %d cannot be an annotation member's value", tag, in.at(-1)));
  }
}
