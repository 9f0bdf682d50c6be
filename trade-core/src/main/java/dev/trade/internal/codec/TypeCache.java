package dev.trade.internal.codec;

import java.lang.ref.WeakReference;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Remembers which class a name resolved to in which loader, because {@link Class#forName} costs more
 * than decoding a small record. Only successful resolutions are kept, at most {@link #MAX_ENTRIES},
 * so hostile input cannot grow it; references are weak, so it keeps no loader or class alive. The
 * allow-list is still consulted on every lookup by the caller, so later refusals take effect.
 *
 * <p>Safe for concurrent use.
 */
final class TypeCache {
  private static final int MAX_ENTRIES = 4096;

  private final ConcurrentHashMap<String, Entry> entries = new ConcurrentHashMap<>();

  /** The class {@code name} resolved to in {@code loader} before, or null. */
  Class<?> get(String name, ClassLoader loader) {
    Entry e = entries.get(name);
    return e != null && e.loader.get() == loader ? e.type.get() : null;
  }

  void put(String name, ClassLoader loader, Class<?> type) {
    if (entries.size() < MAX_ENTRIES) {
      entries.put(name, new Entry(new WeakReference<>(loader), new WeakReference<>(type)));
    }
  }

  private record Entry(WeakReference<ClassLoader> loader, WeakReference<Class<?>> type) {}
}
