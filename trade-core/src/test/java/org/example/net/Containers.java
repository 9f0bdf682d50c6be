package org.example.net;

import dev.trade.TRADEContainer;
import java.util.ArrayList;
import java.util.List;

/** The containers one test builds, closed together after it. Not thread-safe. */
final class Containers implements AutoCloseable {
  private final List<TRADEContainer> built = new ArrayList<>();

  /** A container named {@code name} with the settings {@code key, value, key, value...}. */
  TRADEContainer build(String name, String... settings) {
    TRADEContainer.Builder b = TRADEContainer.builder().name(name);
    for (int i = 0; i < settings.length; i += 2) {
      b.property(settings[i], settings[i + 1]);
    }
    TRADEContainer c = b.build();
    built.add(c);
    return c;
  }

  @Override
  public void close() {
    built.forEach(TRADEContainer::close);
  }
}
