package dev.trade.internal.net.mesh;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.MalformedValueException;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.net.link.Frames;
import dev.trade.internal.net.link.Wire;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Table;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Builds the replication frames (docs/protocol.md, "Replication") and checks the values decoded
 * from them. Stateless; safe for concurrent use as far as the codec passed in is.
 */
public final class StateFrames {
  /** Room for a container id's text when it is read: more is malformed at once. */
  private static final int MAX_ID_TEXT = 64;
  private StateFrames() {}

  public static byte[] links(Topology.LinkState s) {
    ByteSink out = Frames.start(Wire.LINKS, 64 + 40 * s.neighbours().size());
    out.writeText(s.owner());
    out.writeLong(s.version());
    out.writeVarUInt(s.neighbours().size());
    for (String n : s.neighbours()) {
      out.writeText(n);
    }
    return Frames.finish(out);
  }

  public static byte[] table(Codec codec, Table t) {
    ByteSink out = Frames.start(Wire.TABLE, 256);
    out.writeText(t.containerId());
    out.writeLong(t.version());
    writeValue(codec, out, t.services());
    return Frames.finish(out);
  }

  public static byte[] delta(Codec codec, String owner, long version, List<ServiceDescriptor> add,
      List<Long> remove) {
    ByteSink out = Frames.start(Wire.DELTA, 256);
    out.writeText(owner);
    out.writeLong(version);
    writeValue(codec, out, add);
    writeValue(codec, out, remove);
    return Frames.finish(out);
  }

  public static byte[] tableRequest(String owner) {
    ByteSink out = Frames.start(Wire.TABLE_REQUEST, 64);
    out.writeText(owner);
    return Frames.finish(out);
  }

  /** A frame of {@code type} around a payload received unchanged, to pass it on. */
  static byte[] wrap(int type, byte[] payload) {
    ByteSink out = Frames.start(type, payload.length);
    out.writeBytes(payload);
    return Frames.finish(out);
  }

  private static void writeValue(Codec codec, ByteSink out, Object value) {
    try {
      codec.write(value, out);
    } catch (TRADESerializationException e) {
      // Descriptors hold strings, numbers and annotation values only.
      throw new IllegalStateException("cannot encode a service table", e);
    }
  }

  /**
   * The services of {@code owner}'s table: a member speaks only for itself, so every service must
   * name {@code owner} as its container (docs/protocol.md, TABLE).
   *
   * @throws IOException if the value is not a list of service infos, or one names another container
   */
  public static List<ServiceDescriptor> descriptors(Object value, String owner) throws IOException {
    List<ServiceDescriptor> result = new ArrayList<>();
    if (!(value instanceof List)) {
      throw new IOException("service table is not a list");
    }
    for (Object o : (List<?>) value) {
      if (!(o instanceof ServiceDescriptor)) {
        throw new IOException("service table holds a " + (o == null ? "null" : o.getClass().getName()));
      }
      ServiceDescriptor d = (ServiceDescriptor) o;
      if (!d.containerId().equals(owner)) {
        throw new IOException("the table of " + owner + " lists a service of " + d.containerId()
            + " (" + d.signature() + ")");
      }
      result.add(d);
    }
    return result;
  }

  /**
   * A container id: exactly a UUID's canonical text (36 characters, lowercase hexadecimal, hyphens
   * at 8, 13, 18 and 23), as every container writes its own (docs/protocol.md, Container ids).
   * Anything else is malformed: read on, it would stop routing (which parses ids) far from the
   * frame that carried it.
   */
  public static String containerId(ByteSource in) throws MalformedValueException {
    String id = in.readText(MAX_ID_TEXT);
    if (!isContainerId(id)) {
      throw new MalformedValueException("'" + (id.length() > 40 ? id.substring(0, 40) + "…" : id)
          + "' is not a container id (a UUID in its canonical lowercase form)");
    }
    return id;
  }

  /** Whether {@code id} is exactly a UUID's canonical text. */
  public static boolean isContainerId(String id) {
    if (id.length() != 36) {
      return false;
    }
    for (int i = 0; i < 36; i++) {
      char c = id.charAt(i);
      boolean hyphen = i == 8 || i == 13 || i == 18 || i == 23;
      if (hyphen ? c != '-' : !(c >= '0' && c <= '9' || c >= 'a' && c <= 'f')) {
        return false;
      }
    }
    return true;
  }

  static List<Long> ids(Object value) throws IOException {
    List<Long> result = new ArrayList<>();
    if (!(value instanceof List)) {
      throw new IOException("removed ids are not a list");
    }
    for (Object o : (List<?>) value) {
      if (!(o instanceof Long)) {
        throw new IOException("removed id is not a long");
      }
      result.add((Long) o);
    }
    return result;
  }
}
