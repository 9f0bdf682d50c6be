package dev.trade.internal.net.mesh;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Registry;
import java.util.Map;
import java.util.Set;
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
  private final TableKeeper tables;
  /** The newest link-state version of each owner that a reader has queued. */
  private final Map<String, Long> queuedLinks = new ConcurrentHashMap<>();
  /** The newest TABLE version of each owner that a reader has queued. */
  private final Map<String, Long> queuedTables = new ConcurrentHashMap<>();
  /** For each owner, the newest link-state version heard and the links it came over. */
  private final Map<String, Holders> holders = new ConcurrentHashMap<>();

  /** Links that sent one version of a link state: they need no copy of it from here. */
  private static final class Holders {
    final long version;
    final Set<Object> links = ConcurrentHashMap.newKeySet();

    Holders(long version, Object first) {
      this.version = version;
      links.add(first);
    }
  }

  FloodFilter(Topology topology, Registry registry, TableKeeper tables) {
    this.topology = topology;
    this.registry = registry;
    this.tables = tables;
  }

  /**
   * Whether a LINKS, TABLE or DELTA payload ({@code len} bytes of {@code buf} from {@code off},
   * read only during the call) that came over link {@code from} (compared by
   * identity) is a copy of a version applied here already, or queued
   * already from another link (a DELTA: a TABLE at that version or later is queued). A TABLE that
   * passes is kept on the control thread, listed or waiting for a route ({@link TableKeeper}), so a
   * copy of it is never needed again; a DELTA that passes is not counted, since one that does not
   * follow makes the control thread ask for the whole TABLE at that version.
   */
  boolean isStale(Object from, int type, byte[] buf, int off, int len) {
    try {
      ByteSource in = ByteSource.of(buf, off, len);
      String owner = in.readText(MAX_TEXT);
      long version = in.readLong();
      if (type == Wire.LINKS) {
        heard(owner, version, from);
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

  private void heard(String owner, long version, Object from) {
    Holders known = holders.get(owner);
    if (known != null && known.version == version) {
      // Another copy of the newest version: most are, and compute would lock the map's bin for
      // each, with every reader of the container on the same few owners. Should a newer version
      // replace these holders meanwhile, this note is lost, and it no longer matters.
      known.links.add(from);
      return;
    }
    holders.compute(owner, (o, h) -> {
      if (h == null || h.version < version) {
        return new Holders(version, from);
      }
      if (h.version == version) {
        h.links.add(from);
      }
      return h;
    });
  }

  /**
   * Forgets {@code link}, which closed: the holders of an owner's newest version are kept until a
   * newer one comes or the owner is pruned, which for a container that left is a minute, and a
   * closed link held there keeps its buffers.
   */
  void forget(Object link) {
    for (Holders h : holders.values()) {
      h.links.remove(link);
    }
  }

  /**
   * Whether {@code link} needs no copy of {@code owner}'s link state at {@code version} from here:
   * it sent that version here itself, or a newer one is queued here (which is passed on instead).
   * With the control thread behind its links' readers, most neighbours have sent a version by the
   * time it is applied: each version reached a container of 100 about 11 times, once per link.
   */
  boolean hasCopy(Object link, String owner, long version) {
    if (superseded(Wire.LINKS, owner, version)) {
      return true;
    }
    Holders h = holders.get(owner);
    return h != null && h.version == version && h.links.contains(link);
  }

  /**
   * Whether a newer version of {@code owner}'s link state ({@code type} LINKS) or table (TABLE) than
   * {@code version} is queued for the control thread. Applying this one would cost a route
   * computation (or a table decoding) that the newer one undoes at once; it would not be passed on
   * either ({@link #hasCopy}). While the control thread runs behind, a container's versions queue
   * up one after the other: in one 100-container run, 11-27 % of the link states that each JVM's
   * control threads took up were outdated so.
   */
  boolean superseded(int type, String owner, long version) {
    Long queued = (type == Wire.LINKS ? queuedLinks : queuedTables).get(owner);
    return queued != null && queued > version;
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
    holders.keySet().removeIf(owner -> !topology.isStale(owner, Long.MIN_VALUE));
    queuedTables.keySet().removeIf(owner -> !tables.isStale(owner, Long.MIN_VALUE));
  }
}
