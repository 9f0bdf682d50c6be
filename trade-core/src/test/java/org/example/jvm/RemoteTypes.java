package org.example.jvm;

import java.io.Serializable;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * User value types that travel between the test JVM and {@link ProviderMain}, one per kind the
 * codec encodes structurally (or, for {@link Token}, by Java serialization). Both JVMs have them on
 * the class path and allow their package.
 */
public final class RemoteTypes {
  private RemoteTypes() {}

  /** An enum, with one constant that has a body (its class is an anonymous subclass). */
  public enum Gripper {
    OPEN,
    CLOSED,
    JAMMED {
      @Override
      public String toString() {
        return "jammed!";
      }
    }
  }

  public record Pose(double x, double y, double theta, String frame) {}

  /** A record holding other kinds: a list of records, a map with enum values, a set. */
  public record Plan(String name, List<Pose> steps, Map<String, Gripper> grips, Set<Integer> ids) {}

  /** A plain data class: no-argument constructor, fields, no equals. */
  public static class Waypoint {
    String label;
    double x;
    double y;
    int[] weights;
    List<String> tags;
    Gripper grip;
    Pose pose;
    transient String cache = "not sent";

    public Waypoint() {}

    Waypoint(String label, double x, double y, int[] weights, List<String> tags, Gripper grip, Pose pose) {
      this.label = label;
      this.x = x;
      this.y = y;
      this.weights = weights;
      this.tags = tags;
      this.grip = grip;
      this.pose = pose;
      this.cache = "set by the sender";
    }
  }

  /** A data class with a superclass: the fields of both travel. */
  public static final class Checkpoint extends Waypoint {
    long reachedAtMillis;

    public Checkpoint() {}
  }

  /**
   * Serializable, but not a data class (no no-argument constructor): travels by Java serialization,
   * behind the allow-list.
   */
  public static final class Token implements Serializable {
    private static final long serialVersionUID = 1L;
    private final String value;

    public Token(String value) {
      this.value = value;
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof Token && ((Token) o).value.equals(value);
    }

    @Override
    public int hashCode() {
      return value.hashCode();
    }

    @Override
    public String toString() {
      return "Token[" + value + "]";
    }
  }

  @Retention(RetentionPolicy.RUNTIME)
  public @interface Marker {
    int level();

    String[] tags() default {};

    Gripper grip() default Gripper.OPEN;
  }

  /** Carries the annotation instance that travels. */
  @Marker(level = 3, tags = {"arm", "left"}, grip = Gripper.CLOSED)
  public static final class Marked {
    private Marked() {}
  }

  /** A checked exception of the user's, rebuilt as its own class by the caller. */
  public static final class ArmJammedException extends Exception {
    private static final long serialVersionUID = 1L;

    public ArmJammedException(String message, Throwable cause) {
      super(message, cause);
    }
  }
}
