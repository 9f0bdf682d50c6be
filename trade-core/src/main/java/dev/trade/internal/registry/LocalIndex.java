package dev.trade.internal.registry;

/**
 * The container's own services by id: an immutable open-addressing table, replaced as a whole on
 * every registration or deregistration (rare) and read without locks or boxing on every call
 * (often): a local call looks its service up twice, a remote one once on the providing side.
 */
final class LocalIndex {
  static final LocalIndex EMPTY = new LocalIndex(new long[8], new LocalService[8], 0);

  private final long[] ids;
  private final LocalService[] services;
  private final int size;

  private LocalIndex(long[] ids, LocalService[] services, int size) {
    this.ids = ids;
    this.services = services;
    this.size = size;
  }

  private static int slot(long id, int mask) {
    return (int) ((id * 0x9E3779B97F4A7C15L) >>> 40) & mask;
  }

  /** The service with this id, or null. */
  LocalService get(long id) {
    long[] keys = ids;
    int mask = keys.length - 1;
    for (int i = slot(id, mask); ; i = (i + 1) & mask) {
      LocalService s = services[i];
      if (s == null) {
        return null;
      }
      if (keys[i] == id) {
        return s;
      }
    }
  }

  /** This index with {@code s} added (or replacing the service of the same id). */
  LocalIndex with(LocalService s) {
    return rebuild(s, -1);
  }

  /** This index without the service of {@code id}. */
  LocalIndex without(long id) {
    return get(id) == null ? this : rebuild(null, id);
  }

  private LocalIndex rebuild(LocalService add, long remove) {
    int capacity = 8;
    while (capacity < 2 * (size + 1)) {
      capacity <<= 1;
    }
    long[] keys = new long[capacity];
    LocalService[] values = new LocalService[capacity];
    int n = 0;
    for (LocalService s : services) {
      long id = s == null ? 0 : s.descriptor().serviceId();
      if (s != null && id != remove && (add == null || id != add.descriptor().serviceId())) {
        n += put(keys, values, id, s);
      }
    }
    if (add != null) {
      n += put(keys, values, add.descriptor().serviceId(), add);
    }
    return new LocalIndex(keys, values, n);
  }

  private static int put(long[] keys, LocalService[] values, long id, LocalService s) {
    int mask = keys.length - 1;
    int i = slot(id, mask);
    while (values[i] != null) {
      i = (i + 1) & mask;
    }
    keys[i] = id;
    values[i] = s;
    return 1;
  }
}
