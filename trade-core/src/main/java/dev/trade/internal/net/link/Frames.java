package dev.trade.internal.net.link;

import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.MalformedValueException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.UUID;

/**
 * Building and parsing the fixed parts of frames: the frame header, and the routing header that
 * CALL and REPLY frames carry so that containers without a direct link can forward them unread.
 * Stateless.
 */
public final class Frames {
  /** Routing header: source (16), destination (16), hops left (1). */
  public static final int ROUTING = 33;
  private static final VarHandle INTS =
      MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
  private static final VarHandle LONGS =
      MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);

  private Frames() {}

  /** A sink with room for the frame header, which {@link #finish} fills in. */
  public static ByteSink start(int type, int expectedPayload) {
    ByteSink sink = new ByteSink(Wire.HEADER + expectedPayload);
    sink.writeInt(0);
    sink.writeByte(Wire.VERSION);
    sink.writeByte(type);
    return sink;
  }

  /**
   * The finished frame (length filled in). The sink must not be used afterwards: when its array is
   * exactly full, which is how a sink ends after a large array argument or result made it grow,
   * that array is the frame (a 1 MB argument is then not copied once more).
   */
  public static byte[] finish(ByteSink sink) {
    sink.putInt(0, sink.size() - 4);
    return sink.size() == sink.array().length ? sink.array() : sink.toByteArray();
  }

  /** Where a CALL frame (header included) holds its timeout, after routing and the two ids. */
  private static final int CALL_TIMEOUT = Wire.HEADER + ROUTING + 16;
  /**
   * The shortest CALL payload: routing, request id, service id, timeout and the argument count (a
   * byte at least). A shorter one is malformed, whether it is to be served or passed on
   * (docs/protocol.md, CALL).
   */
  public static final int MIN_CALL = ROUTING + 8 + 8 + 4 + 1;
  /** The shortest REPLY payload: routing, request id, status. */
  public static final int MIN_REPLY = ROUTING + 8 + 1;

  /** Whether a complete frame (header included) is a CALL. */
  public static boolean isCall(byte[] frame) {
    return frame.length >= CALL_TIMEOUT + 4 && frame[5] == Wire.CALL;
  }

  /**
   * While a CALL waits to be written, its timeout field holds when it is due instead: {@code now}
   * plus the timeout, in ms of a clock of this container's own (see {@link #unstampDue}).
   */
  static void stampDue(byte[] call, int nowMs) {
    INTS.set(call, CALL_TIMEOUT, nowMs + (int) INTS.get(call, CALL_TIMEOUT));
  }

  /**
   * As a CALL is written: puts the time left until it is due back in its timeout field, so that
   * the next container counts from when it arrives there; false, leaving the frame as it is, when
   * none is left: its caller has given up on it.
   */
  static boolean unstampDue(byte[] call, int nowMs) {
    int left = (int) INTS.get(call, CALL_TIMEOUT) - nowMs; // wraps around with the clock
    if (left <= 0) {
      return false;
    }
    INTS.set(call, CALL_TIMEOUT, left);
    return true;
  }

  /**
   * Takes {@code ms} off the timeout of a CALL payload (header not included) that waits here before
   * it is passed on; false, leaving it as it is, if no more than that is left.
   */
  public static boolean spendCallTime(byte[] callPayload, int ms) {
    int at = CALL_TIMEOUT - Wire.HEADER;
    int left = (int) INTS.get(callPayload, at);
    if (left <= ms) {
      return false;
    }
    INTS.set(callPayload, at, left - ms);
    return true;
  }

  /** The timeout, in ms, of a CALL payload (header not included) of {@link #MIN_CALL} bytes or more. */
  public static int callTimeout(byte[] callPayload) {
    return (int) INTS.get(callPayload, CALL_TIMEOUT - Wire.HEADER);
  }

  /** Whether a complete frame (header included) keeps within {@code limit} (MAXFRAMESIZE). */
  public static boolean fits(byte[] frame, int limit) {
    return frame.length - 4 <= limit;
  }

  static void writeUuid(ByteSink out, UUID id) {
    out.writeLong(id.getMostSignificantBits());
    out.writeLong(id.getLeastSignificantBits());
  }

  static UUID readUuid(ByteSource in) throws MalformedValueException {
    return new UUID(in.readLong(), in.readLong());
  }

  public static void writeRouting(ByteSink out, UUID source, UUID destination, int hops) {
    writeUuid(out, source);
    writeUuid(out, destination);
    out.writeByte(hops);
  }

  /** The payload's destination (routing header at its start). */
  public static UUID destination(byte[] payload) {
    return new UUID(getLong(payload, 16), getLong(payload, 24));
  }

  public static UUID source(byte[] payload) {
    return new UUID(getLong(payload, 0), getLong(payload, 8));
  }

  /** The request id of a CALL or REPLY payload (right after the routing header). */
  public static long requestId(byte[] payload) {
    return getLong(payload, ROUTING);
  }

  public static int hops(byte[] payload) {
    return payload[32] & 0xff;
  }

  /** A frame of {@code type} carrying {@code payload} with one hop fewer left. */
  public static byte[] forwarded(int type, byte[] payload) {
    byte[] frame = new byte[Wire.HEADER + payload.length];
    INTS.set(frame, 0, frame.length - 4);
    frame[4] = (byte) Wire.VERSION;
    frame[5] = (byte) type;
    System.arraycopy(payload, 0, frame, Wire.HEADER, payload.length);
    frame[Wire.HEADER + 32] = (byte) (hops(payload) - 1);
    return frame;
  }

  /** The big-endian {@code long} at {@code at}. */
  public static long getLong(byte[] b, int at) {
    return (long) LONGS.get(b, at);
  }
}
