package dev.trade.internal.hooks;

import dev.trade.TRADEBadArgumentsException;

/** When a hook's wrapper is called, relative to its target. */
public enum Kind {
  /** Before the target, with {@code [serviceName, args...]}; the target waits for it. */
  BEFORE("before"),
  /** After the target, with {@code [serviceName, args..., result]}; the caller waits for it. */
  AFTER("after"),
  /** As {@link #AFTER}, on the hook pool: the caller's result never waits for it. */
  AFTER_ASYNC("after-async");

  private final String label;

  Kind(String label) {
    this.label = label;
  }

  /** The name on the wire (docs/hooks.md). */
  public String label() {
    return label;
  }

  /**
   * The kind named {@code label}.
   *
   * @throws TRADEBadArgumentsException naming the accepted labels
   */
  public static Kind parse(String label) throws TRADEBadArgumentsException {
    for (Kind k : values()) {
      if (k.label.equals(label)) {
        return k;
      }
    }
    throw new TRADEBadArgumentsException("Unknown hook kind '" + label
        + "': use before, after or after-async");
  }

  boolean isAfter() {
    return this != BEFORE;
  }
}
