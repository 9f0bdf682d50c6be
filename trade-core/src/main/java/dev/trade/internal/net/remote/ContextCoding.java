package dev.trade.internal.net.remote;

import dev.trade.internal.call.CallContext;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.MalformedValueException;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A CALL's context on the wire: after the last argument, absent when empty (docs/protocol.md,
 * "Call context"). Stateless.
 */
final class ContextCoding {
  private ContextCoding() {}

  /** Writes {@code context} after a CALL's arguments; nothing when it is empty. */
  static void write(CallContext context, ByteSink out) {
    if (context.isEmpty()) {
      return;
    }
    out.writeVarUInt(context.entries().size());
    for (Map.Entry<String, String> e : context.entries().entrySet()) {
      out.writeText(e.getKey());
      out.writeText(e.getValue());
    }
  }

  /**
   * Reads the context that follows a CALL's arguments: empty when the frame ends there.
   *
   * @throws MalformedValueException if the context breaks a rule of the protocol
   */
  static CallContext read(ByteSource in) throws MalformedValueException {
    if (in.remaining() == 0) {
      return CallContext.EMPTY;
    }
    int count = in.readVarUInt();
    if (count > CallContext.MAX_ENTRIES) {
      throw new MalformedValueException("a call context of " + count + " entries, more than "
          + CallContext.MAX_ENTRIES);
    }
    int start = in.position();
    Map<String, String> entries = new LinkedHashMap<>();
    String previous = null;
    for (int i = 0; i < count; i++) {
      String key = in.readText(CallContext.MAX_KEY);
      String value = in.readText(CallContext.MAX_VALUE);
      if (previous != null && previous.compareTo(key) >= 0) {
        throw new MalformedValueException("call context keys out of order: '" + key + "' after '"
            + previous + "'");
      }
      previous = key;
      entries.put(key, value);
    }
    if (in.position() - start > CallContext.MAX_BYTES) {
      throw new MalformedValueException("a call context of " + (in.position() - start)
          + " bytes, more than " + CallContext.MAX_BYTES);
    }
    try {
      return CallContext.of(entries);
    } catch (IllegalArgumentException e) {
      throw new MalformedValueException(e.getMessage());
    }
  }
}
