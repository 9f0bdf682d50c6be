package dev.trade.internal.hooks;

import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Registry;
import java.io.IOException;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.lang.reflect.Array;
import java.time.Instant;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Writes one JSON line per call it is told of (docs/hooks.md, "The call log"): time, caller
 * container, service, providing container, a summary of the arguments (never a value's
 * {@code toString()}: types and sizes of objects, values of strings, numbers and booleans),
 * duration and outcome. A write that fails is logged once at WARNING and counted. Safe for
 * concurrent use.
 */
final class CallLog {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");
  /** Characters of a string argument the log keeps. */
  static final int STRING_CHARS = 80;

  private final CallLogFile file;
  private final Registry registry;
  private final AtomicBoolean warned = new AtomicBoolean();
  private long failures; // Guarded by this.

  CallLog(CallLogFile file, Registry registry) {
    this.file = file;
    this.registry = registry;
  }

  CallLogFile file() {
    return file;
  }

  /** Logs one call: its hook array, failure and details (see {@link HookLink}). */
  void log(Object[] call, Throwable failure, Map<String, Object> details) {
    try {
      file.write(line(call, failure, details));
    } catch (IOException | RuntimeException e) {
      synchronized (this) {
        failures++;
      }
      if (warned.compareAndSet(false, true)) {
        LOG.log(Level.WARNING, "the call log {0} could not be written: {1}; later failures are"
            + " counted and not logged", file.path(), e.getMessage());
      }
    }
  }

  String line(Object[] call, Throwable failure, Map<String, Object> details) {
    StringBuilder b = new StringBuilder(256).append('{');
    field(b, "time", Instant.ofEpochMilli((Long) details.get("time")).toString()).append(',');
    String caller = (String) details.get("caller");
    field(b, "caller", nameOf(caller)).append(',');
    field(b, "callerId", caller).append(',');
    field(b, "service", (String) details.get("service")).append(',');
    field(b, "provider", (String) details.get("providerName")).append(',');
    field(b, "providerId", (String) details.get("provider")).append(',');
    b.append("\"args\":[");
    for (int i = 1; i < call.length - 1; i++) {
      summary(b.append(i == 1 ? "" : ","), call[i]);
    }
    b.append("],\"micros\":").append(((Long) details.get("nanos")) / 1000.0).append(',');
    field(b, "outcome", failure == null ? "returned" : "threw");
    if (failure != null) {
      Throwable why = failure.getCause() != null ? failure.getCause() : failure;
      field(b.append(','), "error", why.getClass().getName()
          + (why.getMessage() == null ? "" : ": " + why.getMessage()));
    }
    return b.append('}').toString();
  }

  /** The name of container {@code id} as this container knows it, else the id. */
  private String nameOf(String id) {
    for (Entry e : registry.all()) {
      if (e.descriptor().containerId().equals(id)) {
        return e.descriptor().containerName();
      }
    }
    return id;
  }

  private static void summary(StringBuilder b, Object v) {
    if (v == null || v instanceof Boolean || v instanceof Integer || v instanceof Long
        || v instanceof Short || v instanceof Byte) {
      b.append(v);
    } else if (v instanceof Number n && Double.isFinite(n.doubleValue())) {
      b.append(n);
    } else if (v instanceof CharSequence || v instanceof Character || v instanceof Enum<?>) {
      String s = v instanceof Enum<?> e ? e.name() : v.toString();
      string(b, s.length() > STRING_CHARS ? s.substring(0, STRING_CHARS) + "…" : s);
    } else if (v.getClass().isArray()) {
      string(b, v.getClass().getComponentType().getSimpleName() + "[" + Array.getLength(v) + "]");
    } else if (v instanceof Collection<?> c) {
      string(b, (v instanceof List ? "List" : v instanceof Set ? "Set" : "Collection") + "("
          + c.size() + ")");
    } else if (v instanceof Map<?, ?> m) {
      string(b, "Map(" + m.size() + ")");
    } else {
      string(b, v.getClass().getName());
    }
  }

  private static StringBuilder field(StringBuilder b, String name, String value) {
    return string(b.append('"').append(name).append("\":"), value);
  }

  /** {@code s} as a JSON string. */
  static StringBuilder string(StringBuilder b, String s) {
    b.append('"');
    for (int i = 0; i < s.length(); i++) {
      char c = s.charAt(i);
      switch (c) {
        case '"' -> b.append("\\\"");
        case '\\' -> b.append("\\\\");
        case '\n' -> b.append("\\n");
        case '\r' -> b.append("\\r");
        case '\t' -> b.append("\\t");
        default -> {
          if (c < 0x20) {
            b.append(String.format("\\u%04x", (int) c));
          } else {
            b.append(c);
          }
        }
      }
    }
    return b.append('"');
  }

  synchronized long failures() {
    return failures;
  }

  void close() {
    try {
      file.close();
    } catch (IOException e) {
      LOG.log(Level.DEBUG, "closing the call log {0}: {1}", file.path(), e.getMessage());
    }
  }
}
