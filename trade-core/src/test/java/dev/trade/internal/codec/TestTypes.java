package dev.trade.internal.codec;

import dev.trade.internal.registry.ServiceDescriptor;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/** Value types shared by the codec tests. */
final class TestTypes {
  private TestTypes() {}

  /** A codec that allows this test package besides the defaults. */
  static Codec codec() {
    return codec(Limits.DEFAULT);
  }

  static Codec codec(Limits limits) {
    AllowList allow = AllowList.withDefaults();
    allow.add("dev.trade.internal.codec.*");
    return new Codec(allow, limits, new FakeBinding());
  }

  /** A codec with only the default allow-list: this test package is refused. */
  static Codec strangerCodec() {
    return new Codec(AllowList.withDefaults(), Limits.DEFAULT, new FakeBinding());
  }

  static ClassLoader loader() {
    return TestTypes.class.getClassLoader();
  }

  enum Color { RED, GREEN, BLUE }

  enum Op {
    PLUS { @Override int apply(int a, int b) { return a + b; } },
    TIMES { @Override int apply(int a, int b) { return a * b; } };

    abstract int apply(int a, int b);
  }

  /** A logic term, like DIARC's: an abstract type held in typed arrays. */
  abstract static class Term {}

  record Symbol(String name) {}

  record Point(int x, int y) {}

  record Labeled(String label, Point point, List<String> tags, double weight, Color color) {}

  record Positive(int value) {
    Positive {
      if (value <= 0) {
        throw new IllegalArgumentException("not positive: " + value);
      }
    }
  }

  record Holder(Object value) {}

  /** A plain data class: private fields, a final one, a transient one, a private constructor. */
  static class Pose extends Base {
    private double x;
    private double y;
    private final String frame;
    transient int cached = 7;
    static int instances;
    private List<Integer> history = new ArrayList<>();
    private TreeMap<String, Integer> sorted = new TreeMap<>();

    private Pose() {
      frame = "none";
    }

    Pose(long id, double x, double y, String frame) {
      super(id);
      this.x = x;
      this.y = y;
      this.frame = frame;
    }

    String frame() {
      return frame;
    }

    List<Integer> history() {
      return history;
    }

    TreeMap<String, Integer> sorted() {
      return sorted;
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof Pose p && p.id() == id() && p.x == x && p.y == y
          && p.frame.equals(frame) && p.history.equals(history) && p.sorted.equals(sorted)
          && Objects.equals(p.shadowedInBase(), shadowedInBase()) && Objects.equals(p.name, name);
    }

    @Override
    public int hashCode() {
      return Objects.hash(id(), x, y, frame);
    }

    String name = "pose";
  }

  static class Base extends Term {
    private long id;
    String name = "base"; // shadowed by Pose.name

    Base() {}

    Base(long id) {
      this.id = id;
    }

    long id() {
      return id;
    }

    String shadowedInBase() {
      return name;
    }
  }

  /** Serializable with its own hooks: travels as Java serialization. */
  static final class Legacy implements Serializable {
    private static final long serialVersionUID = 1L;
    private transient String text;

    Legacy(String text) {
      this.text = text;
    }

    String text() {
      return text;
    }

    private void writeObject(ObjectOutputStream out) throws IOException {
      out.writeUTF(text);
    }

    private void readObject(ObjectInputStream in) throws IOException {
      text = in.readUTF();
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof Legacy l && l.text.equals(text);
    }

    @Override
    public int hashCode() {
      return text.hashCode();
    }
  }

  /** Neither a record, a data class (no no-argument constructor) nor Serializable. */
  static final class NotCodable {
    final int value;

    NotCodable(int value) {
      this.value = value;
    }
  }

  static class RobotException extends Exception {
    private static final long serialVersionUID = 1L;

    RobotException(String message, Throwable cause) {
      super(message, cause);
    }
  }

  static class NoMessageException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    NoMessageException() {}
  }

  @Retention(RetentionPolicy.RUNTIME)
  @interface Inner {
    int value();
  }

  @Retention(RetentionPolicy.RUNTIME)
  @interface Action {
    String value();

    int priority() default 5;

    String[] tags() default {};

    Color color() default Color.GREEN;

    Class<?> type() default Object.class;

    Inner inner() default @Inner(1);

    long[] limits() default {1L, 2L};

    char letter() default 'x';

    double ratio() default 0.5;
  }

  /** Stands in for TRADEServiceInfo: a handle around a descriptor, equal by descriptor. */
  static final class FakeInfo {
    final ServiceDescriptor descriptor;

    FakeInfo(ServiceDescriptor descriptor) {
      this.descriptor = descriptor;
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof FakeInfo f && f.descriptor.equals(descriptor);
    }

    @Override
    public int hashCode() {
      return descriptor.hashCode();
    }
  }

  static final class FakeBinding implements InfoBinding {
    @Override
    public ServiceDescriptor describe(Object value) {
      return value instanceof FakeInfo f ? f.descriptor : null;
    }

    @Override
    public Object bind(ServiceDescriptor descriptor) {
      return new FakeInfo(descriptor);
    }
  }

  static ServiceDescriptor descriptor(java.lang.annotation.Annotation... annotations) {
    return new ServiceDescriptor("c-1", "robot", "10.0.0.2", 42, "moveTo",
        List.of("x", "y"), List.of("double", "double"), "boolean",
        new java.util.LinkedHashSet<>(List.of("agent:hugo", "motion")), List.of(annotations));
  }

  static Map<String, Object> nested() {
    Map<String, Object> map = new java.util.LinkedHashMap<>();
    map.put("list", new ArrayList<>(List.of(1, "two", 3.0, List.of(Map.of("k", 'v')))));
    map.put("set", new java.util.LinkedHashSet<>(List.of("z", "a", "m")));
    map.put(null, null);
    return map;
  }
}
