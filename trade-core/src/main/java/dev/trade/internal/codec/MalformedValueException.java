package dev.trade.internal.codec;

import dev.trade.TRADESerializationException;

/**
 * The bytes are not a valid encoded value: unknown tag, truncated input, invalid UTF-8, a count or
 * length beyond the decoder's {@link Limits}, nesting deeper than allowed, or trailing garbage.
 *
 * <p>It is a {@link TRADESerializationException} so that callers that only care whether a value
 * could travel need one catch clause. Callers that need to tell "the peer sent garbage" from "the
 * value names a class that is refused or unknown here" catch this type first. Values are always
 * embedded in length-delimited frames, so neither kind corrupts the enclosing stream.
 */
public class MalformedValueException extends TRADESerializationException {
  private static final long serialVersionUID = 1L;

  public MalformedValueException(String message) {
    super(message);
  }

  public MalformedValueException(String message, Throwable cause) {
    super(message, cause);
  }
}
