package dev.trade.internal.codec;

/**
 * The one-byte type tags of wire format version 1; {@code docs/protocol.md} is the specification.
 * Tags {@code 0x80..0xFF} are reserved and always malformed in version 1.
 */
final class Tags {
  static final int NULL = 0x00;
  static final int FALSE = 0x01;
  static final int TRUE = 0x02;
  static final int INT8 = 0x03;
  static final int INT16 = 0x04;
  static final int INT32 = 0x05;
  static final int INT64 = 0x06;
  static final int FLOAT32 = 0x07;
  static final int FLOAT64 = 0x08;
  static final int CHAR = 0x09;
  static final int STRING = 0x0A;

  static final int BYTES = 0x10;
  static final int BOOLEANS = 0x11;
  static final int SHORTS = 0x12;
  static final int CHARS = 0x13;
  static final int INTS = 0x14;
  static final int LONGS = 0x15;
  static final int FLOATS = 0x16;
  static final int DOUBLES = 0x17;
  static final int ARRAY = 0x18;

  static final int LIST = 0x20;
  static final int SET = 0x21;
  static final int MAP = 0x22;

  static final int ENUM = 0x30;
  static final int RECORD = 0x31;
  static final int OBJECT = 0x32;
  static final int THROWABLE = 0x33;
  static final int SERVICE_INFO = 0x34;
  static final int ANNOTATION = 0x35;
  static final int CLASS = 0x36;

  static final int BIG_INTEGER = 0x40;
  static final int BIG_DECIMAL = 0x41;
  static final int UUID = 0x42;
  static final int INSTANT = 0x43;
  static final int DURATION = 0x44;

  static final int JAVA = 0x50;

  /** The longest type name, member name or component name, in UTF-8 bytes (the class file limit). */
  static final int MAX_NAME_BYTES = 65535;

  /** The most causes an encoder writes below an exception; deeper causes are dropped. */
  static final int MAX_CAUSES = 16;

  private Tags() {}
}
