package dev.trade.internal.registry;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * An immutable view of every known service, published by the {@link Registry} after each change
 * and read by lookups without locking: all entries in order of preference, and indexes by name
 * and by identity.
 */
record Snapshot(List<Entry> ordered, Map<String, List<Entry>> byName, Map<Snapshot.Key, Entry> byKey) {
  /** By distance, then container id, then service id. */
  private static final Comparator<Entry> PREFERENCE = new Comparator<>() {
    @Override
    public int compare(Entry a, Entry b) {
      int c = Integer.compare(a.distance(), b.distance());
      if (c == 0) {
        c = a.descriptor().containerId().compareTo(b.descriptor().containerId());
      }
      return c != 0 ? c : Long.compare(a.descriptor().serviceId(), b.descriptor().serviceId());
    }
  };

  static final Snapshot EMPTY = new Snapshot(List.of(), Map.of(), Map.of());

  /** The entry of the service {@code d} describes, or null. */
  Entry entry(ServiceDescriptor d) {
    return byKey.get(new Key(d.containerId(), d.serviceId()));
  }

  static Snapshot of(Map<String, Map<Long, Entry>> tables) {
    List<Entry> all = new ArrayList<>();
    for (Map<Long, Entry> t : tables.values()) {
      all.addAll(t.values());
    }
    all.sort(PREFERENCE);
    Map<String, List<Entry>> byName = new HashMap<>();
    Map<Key, Entry> byKey = new HashMap<>();
    for (Entry e : all) {
      List<Entry> named = byName.get(e.descriptor().name());
      if (named == null) {
        named = new ArrayList<>();
        byName.put(e.descriptor().name(), named);
      }
      named.add(e);
      byKey.put(new Key(e.descriptor().containerId(), e.descriptor().serviceId()), e);
    }
    for (Map.Entry<String, List<Entry>> e : byName.entrySet()) {
      e.setValue(List.copyOf(e.getValue()));
    }
    return new Snapshot(List.copyOf(all), Map.copyOf(byName), Map.copyOf(byKey));
  }

  /**
   * A service's identity as a map key. A class rather than a record: a record's equals and
   * hashCode are generated at run time on first use, which costs a starting container about 20
   * method-handle classes (see docs/benchmarks-log.md, "Start → callable").
   */
  static final class Key {
    private final String containerId;
    private final long serviceId;

    Key(String containerId, long serviceId) {
      this.containerId = containerId;
      this.serviceId = serviceId;
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof Key && ((Key) o).serviceId == serviceId
          && ((Key) o).containerId.equals(containerId);
    }

    @Override
    public int hashCode() {
      return 31 * containerId.hashCode() + Long.hashCode(serviceId);
    }
  }

}
