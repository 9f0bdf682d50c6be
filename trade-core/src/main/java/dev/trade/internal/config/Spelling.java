package dev.trade.internal.config;

/**
 * How far apart two names are, for the library's other "did you mean" (service names), measured
 * as misspelled configuration keys are. Stateless.
 */
public final class Spelling {
  private Spelling() {}

  /** Levenshtein distance: insertions, deletions and substitutions each cost 1. */
  public static int distance(String a, String b) {
    return Key.distance(a, b);
  }
}
