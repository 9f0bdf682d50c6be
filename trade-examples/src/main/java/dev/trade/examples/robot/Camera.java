package dev.trade.examples.robot;

import java.io.PrintStream;
import java.util.Map;
import java.util.Objects;

/**
 * A simulated {@link Vision} with a fixed scene: a cup and a box on the table. It prints only when
 * it finds something, so that a caller polling it does not flood the transcript. Immutable and
 * safe for concurrent use.
 */
public final class Camera implements Vision {
  private static final Map<String, Detection> SCENE = Map.of(
      "cup", new Detection("cup", new Pose(0.40, 0.10, 0.02), 0.93),
      "box", new Detection("box", new Pose(0.55, -0.20, 0.05), 0.88));

  private final PrintStream out;

  /** A camera that reports what it finds to {@code out}. */
  public Camera(PrintStream out) {
    this.out = Objects.requireNonNull(out, "out == null");
  }

  @Override
  public Detection checkFor(String objectType) {
    Objects.requireNonNull(objectType, "objectType == null");
    Detection d = SCENE.getOrDefault(objectType, Detection.none(objectType));
    if (d.found()) {
      out.println("found " + d);
    }
    return d;
  }
}
