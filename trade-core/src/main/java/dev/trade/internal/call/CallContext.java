package dev.trade.internal.call;

import java.nio.charset.StandardCharsets;
import java.util.Collections;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * The small key/value context a call carries to the provider's host chain (a lock token, for
 * example), in the CALL frame when the call is remote (docs/protocol.md, "Call context"). Keys
 * starting with {@code trade.} are reserved for the middleware; none is defined yet. Immutable,
 * so safe for concurrent use; its entries iterate in the order the protocol writes them.
 */
public final class CallContext {
  /** The most entries a context holds. */
  public static final int MAX_ENTRIES = 16;
  /** The longest key, in bytes of UTF-8. */
  public static final int MAX_KEY = 64;
  /** The longest value, in bytes of UTF-8. */
  public static final int MAX_VALUE = 1024;
  /** The most bytes all entries take together, length prefixes included. */
  public static final int MAX_BYTES = 4096;

  public static final CallContext EMPTY = new CallContext(Collections.emptySortedMap());

  private final SortedMap<String, String> entries;

  private CallContext(SortedMap<String, String> entries) {
    this.entries = entries;
  }

  /**
   * A context of {@code entries}.
   *
   * @throws IllegalArgumentException naming the entry that breaks a rule of the protocol
   */
  public static CallContext of(Map<String, String> entries) {
    if (entries.isEmpty()) {
      return EMPTY;
    }
    if (entries.size() > MAX_ENTRIES) {
      throw new IllegalArgumentException("a call context holds at most " + MAX_ENTRIES
          + " entries, not " + entries.size());
    }
    // Byte order of UTF-8 is the order of the allowed key characters (ASCII) as Java compares them.
    TreeMap<String, String> sorted = new TreeMap<>();
    int bytes = 0;
    for (Map.Entry<String, String> e : entries.entrySet()) {
      String key = e.getKey();
      String value = e.getValue();
      checkKey(key);
      int valueBytes = value.getBytes(StandardCharsets.UTF_8).length;
      if (valueBytes > MAX_VALUE) {
        throw new IllegalArgumentException("the value of call context key '" + key + "' takes "
            + valueBytes + " bytes, more than " + MAX_VALUE);
      }
      bytes += prefix(key.length()) + key.length() + prefix(valueBytes) + valueBytes;
      sorted.put(key, value);
    }
    if (bytes > MAX_BYTES) {
      throw new IllegalArgumentException("a call context takes at most " + MAX_BYTES
          + " bytes, this one " + bytes);
    }
    return new CallContext(Collections.unmodifiableSortedMap(sorted));
  }

  private static void checkKey(String key) {
    boolean ok = !key.isEmpty() && key.length() <= MAX_KEY && key.charAt(0) >= 'a'
        && key.charAt(0) <= 'z';
    for (int i = 0; ok && i < key.length(); i++) {
      char c = key.charAt(i);
      ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
    }
    if (!ok) {
      throw new IllegalArgumentException("'" + key + "' is not a call context key: 1 to " + MAX_KEY
          + " of a-z 0-9 . _ -, starting with a letter");
    }
  }

  /** Bytes of a uvarint length prefix. */
  private static int prefix(int n) {
    return n < 0x80 ? 1 : n < 0x4000 ? 2 : 3;
  }

  public boolean isEmpty() {
    return entries.isEmpty();
  }

  /** The value of {@code key}, or null if there is none. */
  public String get(String key) {
    return entries.get(key);
  }

  /** The entries in increasing key order: unmodifiable. */
  public SortedMap<String, String> entries() {
    return entries;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof CallContext c && c.entries.equals(entries);
  }

  @Override
  public int hashCode() {
    return entries.hashCode();
  }

  @Override
  public String toString() {
    return entries.toString();
  }
}
