package dev.trade.internal.net;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.registry.Registry;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Lets a link's reader drop the copies of a flood before they queue for the control thread: each
 * version of a link state or table arrives over every link of a container, and with 100 containers
 * the control threads ran seconds behind on copies. It reads a frame's owner and version, nothing
 * else; the control thread checks again whatever passes.
 *
 * <p>{@link #isStale} is safe for concurrent use; {@link #pruned} runs on the control thread.
 */
final class FloodFilter {
  private static final int MAX_TEXT = 1024;

  private final Topology topology;
  private final Registry registry;
  private final Tables tables;
  /** The newest link-state version of each owner that a reader has queued. */
  private final Map<String, Long> queuedLinks = new ConcurrentHashMap<>();
  /** The newest TABLE version of each owner that a reader has queued. */
  private final Map<String, Long> queuedTables = new ConcurrentHashMap<>();

  FloodFilter(Topology topology, Registry registry, Tables tables) {
    this.topology = topology;
    this.registry = registry;
    this.tables = tables;
  }

  /**
   * Whether a LINKS, TABLE or DELTA payload is a copy of a version applied here already, or queued
   * already from another link (a DELTA: a TABLE at that version or later is queued). A TABLE that
   * passes is kept on the control thread, listed or waiting for a route ({@link Tables}), so a
   * copy of it is never needed again; a DELTA that passes is not counted, since one that does not
   * follow makes the control thread ask for the whole TABLE at that version.
   */
  boolean isStale(int type, byte[] payload) {
    try {
      ByteSource in = ByteSource.of(payload);
      String owner = in.readText(MAX_TEXT);
      long version = in.readLong();
      if (type == Wire.LINKS) {
        // While the control thread runs behind, every copy of a new version passes the check.
        return topology.isStale(owner, version) || queued(queuedLinks, owner, version);
      }
      Long table = queuedTables.get(owner);
      if (table != null && table >= version) {
        return true; // checked first: the registry's check takes its lock
      }
      if (registry.isStale(owner, version)) {
        return true;
      }
      return type == Wire.TABLE && queued(queuedTables, owner, version);
    } catch (TRADESerializationException | RuntimeException e) {
      return false; // malformed: the control thread closes the link
    }
  }

  /** Records {@code version} as queued for {@code owner}; whether one as new was queued before. */
  private static boolean queued(Map<String, Long> queued, String owner, long version) {
    long[] was = {Long.MIN_VALUE};
    queued.merge(owner, version, (old, v) -> {
      was[0] = old;
      return Math.max(old, v);
    });
    return was[0] >= version;
  }

  /**
   * Forgets what was queued for owners whose states or tables were pruned: they may be learnt
   * again, at any version. (One still queued then is only queued once more from another link:
   * applied once, dropped as stale after.)
   */
  void pruned() {
    queuedLinks.keySet().removeIf(owner -> !topology.isStale(owner, Long.MIN_VALUE));
    queuedTables.keySet().removeIf(owner -> !tables.isStale(owner, Long.MIN_VALUE));
  }
}
