package dev.trade.internal.net;

/**
 * Frame layout constants of the connection protocol (docs/protocol.md, "Frames"). Every frame is
 * {@code u32 length | u8 version | u8 type | payload}, where length counts the bytes after itself.
 */
final class Wire {
  static final int VERSION = 1;
  static final int HEADER = 4 + 1 + 1;
  /** Frames a peer may send before it has authenticated are small and fixed-layout. */
  static final int MAX_HANDSHAKE_FRAME = 4096;
  /** The smallest MAXFRAMESIZE a container may have, and may declare in its HELLO. */
  static final int MIN_FRAME_LIMIT = 1024;

  // Before authentication.
  static final int HELLO = 1;
  static final int AUTH = 2;
  static final int REFUSE = 3;
  // After authentication.
  static final int PING = 10;
  static final int GOODBYE = 11;
  static final int LINKS = 20;
  static final int TABLE = 21;
  static final int DELTA = 22;
  static final int TABLE_REQUEST = 23;
  static final int DIGEST = 24;
  static final int CALL = 30;
  static final int REPLY = 31;

  // REPLY status codes.
  static final int OK = 0;
  static final int FAILED_INVOCATION = 1;
  static final int FAILED_UNAVAILABLE = 2;
  static final int FAILED_BAD_ARGUMENTS = 3;
  static final int FAILED_SERIALIZATION = 4;
  static final int FAILED_TIMEOUT = 5;
  static final int FAILED_OTHER = 6;

  // REFUSE reasons.
  static final int REFUSE_VERSION = 1;
  static final int REFUSE_SYSTEM = 2;
  static final int REFUSE_CREDENTIALS = 3;
  static final int REFUSE_SELF = 4;
  static final int REFUSE_MALFORMED = 5;
  static final int REFUSE_ENCRYPTION = 6;

  /** Forwarded frames die after this many hops, whatever the routing tables say. */
  static final int MAX_HOPS = 16;

  private Wire() {}
}
