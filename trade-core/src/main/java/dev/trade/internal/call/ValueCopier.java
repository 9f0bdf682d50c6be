package dev.trade.internal.call;

import dev.trade.TRADESerializationException;
import java.util.Set;

/**
 * Copies a value so that two parties never share a mutable object (strict local calls); immutable
 * values may be returned as they are. Implementations are thread-safe.
 */
public interface ValueCopier {
  /**
   * Copies {@code value}, resolving class names in {@code loader} and allowing those in
   * {@code declared} (the classes the service's signature declares) besides the allow-list.
   */
  Object copy(Object value, ClassLoader loader, Set<String> declared)
      throws TRADESerializationException;
}
