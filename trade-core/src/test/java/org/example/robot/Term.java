package org.example.robot;

import java.util.Objects;

/** A user value type with a subtype, as DIARC's Term and Predicate. */
public class Term {
  final String name;

  public Term(String name) {
    this.name = name;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof Term && ((Term) o).name.equals(name);
  }

  @Override
  public int hashCode() {
    return Objects.hash(name);
  }

  /** A subtype, as DIARC's Predicate extends Term. */
  public static class Predicate extends Term {
    public Predicate(String name) {
      super(name);
    }
  }
}
