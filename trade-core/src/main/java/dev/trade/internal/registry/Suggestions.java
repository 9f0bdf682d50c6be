package dev.trade.internal.registry;

import dev.trade.internal.config.Spelling;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The "did you mean" of a lookup that found nothing: the services whose names are nearest to the
 * one asked for, with their signatures, as configuration keys suggest their nearest key. Stateless.
 */
public final class Suggestions {
  /** At most this many services are listed; a longer list helps less than it costs to read. */
  static final int MAX = 5;

  private Suggestions() {}

  /**
   * A text to append to "no service matches …": the services named {@code name} (when the name
   * was right but something else did not match), else those of the nearest names; empty when no
   * name was asked for or none is near.
   *
   * @param known every known service, in preference order
   */
  public static String hint(List<Entry> known, String name) {
    if (name == null) {
      return "";
    }
    List<String> exact = new ArrayList<>();
    int best = Integer.MAX_VALUE;
    List<Entry> nearest = new ArrayList<>();
    String lower = name.toLowerCase(Locale.ROOT);
    for (Entry e : known) {
      String n = e.descriptor().name();
      if (n.equals(name)) {
        exact.add(describe(e));
        continue;
      }
      int d = Spelling.distance(lower, n.toLowerCase(Locale.ROOT));
      if (d < best) {
        best = d;
        nearest.clear();
      }
      if (d == best) {
        nearest.add(e);
      }
    }
    if (!exact.isEmpty()) {
      return "; services named " + name + ": " + list(exact);
    }
    // A suggestion further away than this is noise rather than help (the same rule as for keys).
    if (nearest.isEmpty() || best > Math.max(2, name.length() / 3)) {
      return "";
    }
    List<String> texts = new ArrayList<>();
    nearest.forEach(e -> texts.add(describe(e)));
    return "; did you mean " + list(texts) + "?";
  }

  private static String describe(Entry e) {
    ServiceDescriptor d = e.descriptor();
    return d.returnTypeName() + " " + d.signature() + (d.groups().isEmpty() ? "" : " " + d.groups())
        + " @ " + d.containerName();
  }

  private static String list(List<String> texts) {
    if (texts.size() <= MAX) {
      return String.join(", ", texts);
    }
    return String.join(", ", texts.subList(0, MAX)) + " and " + (texts.size() - MAX) + " more";
  }
}
