package dev.trade.internal.net.link;

/**
 * Frame layout constants of the connection protocol (docs/protocol.md, "Frames"). Every frame is
 * {@code u32 length | u8 version | u8 type | payload}, where length counts the bytes after itself.
 */
public final class Wire {
  public static final int VERSION = 1;
  public static final int HEADER = 4 + 1 + 1;
  /** Frames a peer may send before it has authenticated are small and fixed-layout. */
  public static final int MAX_HANDSHAKE_FRAME = 4096;
  /** The smallest MAXFRAMESIZE a container may have, and may declare in its HELLO. */
  static final int MIN_FRAME_LIMIT = 1024;

  // Before authentication.
  public static final int HELLO = 1;
  public static final int AUTH = 2;
  public static final int REFUSE = 3;
  // After authentication.
  public static final int PING = 10;
  public static final int GOODBYE = 11;
  public static final int LINKS = 20;
  public static final int TABLE = 21;
  public static final int DELTA = 22;
  public static final int TABLE_REQUEST = 23;
  public static final int DIGEST = 24;
  public static final int CALL = 30;
  public static final int REPLY = 31;

  // REPLY status codes.
  public static final int OK = 0;
  public static final int FAILED_INVOCATION = 1;
  public static final int FAILED_UNAVAILABLE = 2;
  public static final int FAILED_BAD_ARGUMENTS = 3;
  public static final int FAILED_SERIALIZATION = 4;
  public static final int FAILED_TIMEOUT = 5;
  public static final int FAILED_OTHER = 6;
  public static final int FAILED_LOCKED = 7;
  /** The provider's access control refused the call (docs/protocol.md, "Proof of a principal"). */
  public static final int FAILED_NOT_AUTHORIZED = 8;

  // REFUSE reasons.
  static final int REFUSE_VERSION = 1;
  static final int REFUSE_SYSTEM = 2;
  static final int REFUSE_CREDENTIALS = 3;
  static final int REFUSE_SELF = 4;
  public static final int REFUSE_MALFORMED = 5;
  static final int REFUSE_ENCRYPTION = 6;

  /** Forwarded frames die after this many hops, whatever the routing tables say. */
  public static final int MAX_HOPS = 16;

  private Wire() {}
}
