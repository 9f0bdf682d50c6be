package dev.trade.internal.net.mesh;

import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.MalformedValueException;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.Table;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The link-up exchange of two containers that both set the DIGEST flag in their HELLO
 * (docs/protocol.md, "DIGEST"): each sends the versions it has of every container's link state and
 * service table, and answers the other's digest with only what that one lacks. A container that
 * links again to a neighbour that knows the system then sends a few frames, not a link state and a
 * table per container; with 100 containers on one host the full exchanges of the links that kept
 * coming up ran the control threads seconds behind.
 *
 * <p>Stateless; its callers run on the control thread.
 */
public final class Digest {
  /** The version sent for a link state or table the sender does not have. */
  static final long NONE = -1;
  private static final int MAX_ENTRIES = 65_536;

  private Digest() {}

  /** The DIGEST frame: every owner of a link state or table, with the versions of both. */
  public static byte[] frame(Collection<Topology.LinkState> states, Table own, List<Table> tables) {
    Map<String, long[]> versions = new HashMap<>();
    for (Topology.LinkState s : states) {
      versions.computeIfAbsent(s.owner(), o -> new long[] {NONE, NONE})[0] = s.version();
    }
    versions.computeIfAbsent(own.containerId(), o -> new long[] {NONE, NONE})[1] = own.version();
    for (Table t : tables) {
      versions.computeIfAbsent(t.containerId(), o -> new long[] {NONE, NONE})[1] = t.version();
    }
    ByteSink out = Frames.start(Wire.DIGEST, 16 + 56 * versions.size());
    out.writeVarUInt(versions.size());
    for (Map.Entry<String, long[]> e : versions.entrySet()) {
      out.writeText(e.getKey());
      out.writeLong(e.getValue()[0]);
      out.writeLong(e.getValue()[1]);
    }
    return Frames.finish(out);
  }

  /**
   * What the sender of a DIGEST lacks, in the order of the full exchange: link states newer than
   * the ones it has (this container's own included), then this container's table, then the other
   * tables, each only if newer than the sender's.
   *
   * @throws MalformedValueException if the payload is malformed
   */
  static List<byte[]> answer(byte[] payload, Collection<Topology.LinkState> states,
      Table own, List<Table> tables, Codec codec) throws MalformedValueException {
    Map<String, long[]> theirs = read(payload);
    List<byte[]> frames = new ArrayList<>();
    for (Topology.LinkState s : states) {
      if (s.version() > have(theirs, s.owner())[0]) {
        frames.add(StateFrames.links(s));
      }
    }
    if (own.version() > have(theirs, own.containerId())[1]) {
      frames.add(StateFrames.table(codec, own));
    }
    for (Table t : tables) {
      if (t.version() > have(theirs, t.containerId())[1]) {
        frames.add(StateFrames.table(codec, t));
      }
    }
    return frames;
  }

  private static long[] have(Map<String, long[]> theirs, String owner) {
    return theirs.getOrDefault(owner, new long[] {NONE, NONE});
  }

  /**
   * The versions a DIGEST lists, by owner.
   *
   * @throws MalformedValueException if the payload is malformed
   */
  public static Map<String, long[]> read(byte[] payload) throws MalformedValueException {
    ByteSource in = ByteSource.of(payload);
    int n = in.readVarUInt();
    if (n > MAX_ENTRIES) {
      throw new MalformedValueException("digest with " + n + " entries");
    }
    Map<String, long[]> result = new HashMap<>();
    for (int i = 0; i < n; i++) {
      String owner = StateFrames.containerId(in);
      result.put(owner, new long[] {in.readLong(), in.readLong()});
    }
    return result;
  }
}
