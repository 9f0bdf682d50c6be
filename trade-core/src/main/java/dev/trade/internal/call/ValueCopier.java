package dev.trade.internal.call;

import dev.trade.TRADESerializationException;

/**
 * Copies a value so that two parties never share a mutable object (strict local calls); immutable
 * values may be returned as they are. Implementations are thread-safe.
 */
public interface ValueCopier {
  /** Copies {@code value}, resolving class names in {@code loader}. */
  Object copy(Object value, ClassLoader loader) throws TRADESerializationException;
}
