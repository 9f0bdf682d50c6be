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
  /** The newest link-state version of each owner that a reader has queued. */
  private final Map<String, Long> queuedLinks = new ConcurrentHashMap<>();

  FloodFilter(Topology topology, Registry registry) {
    this.topology = topology;
    this.registry = registry;
  }

  /**
   * Whether a LINKS, TABLE or DELTA payload is a copy of a version applied here already, or (for
   * LINKS) queued already from another link. Tables are not filtered by what is queued: one that
   * the control thread drops (its owner just went away) may be asked for again at the same version.
   */
  boolean isStale(int type, byte[] payload) {
    try {
      ByteSource in = ByteSource.of(payload);
      String owner = in.readText(MAX_TEXT);
      long version = in.readLong();
      if (type != Wire.LINKS) {
        return registry.isStale(owner, version);
      }
      if (topology.isStale(owner, version)) {
        return true;
      }
      // While the control thread runs behind, every copy of a new version passes the check above.
      long[] was = {Long.MIN_VALUE};
      queuedLinks.merge(owner, version, (old, v) -> {
        was[0] = old;
        return Math.max(old, v);
      });
      return was[0] >= version;
    } catch (TRADESerializationException | RuntimeException e) {
      return false; // malformed: the control thread closes the link
    }
  }

  /**
   * Forgets what was queued for owners whose states the topology pruned: they may be learnt again,
   * at any version. (A state still queued then is only queued once more from another link: applied
   * once, dropped as stale after.)
   */
  void pruned() {
    queuedLinks.keySet().removeIf(owner -> !topology.isStale(owner, Long.MIN_VALUE));
  }
}
