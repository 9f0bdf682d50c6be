package dev.trade.examples.robot;

import java.util.Locale;
import java.util.Objects;

/**
 * What {@link Vision#checkFor(String)} saw: whether an object of the asked type is in view and, if
 * so, where and how sure the camera is.
 *
 * @param objectType the type that was asked for
 * @param pose where the object is; null when it was not found
 * @param confidence 0..1; 0 when it was not found
 */
public record Detection(String objectType, Pose pose, double confidence) {
  public Detection {
    Objects.requireNonNull(objectType, "objectType == null");
    if (confidence < 0 || confidence > 1) {
      throw new IllegalArgumentException("confidence must be in 0..1: " + confidence);
    }
  }

  /** A detection saying that no {@code objectType} is in view. */
  public static Detection none(String objectType) {
    return new Detection(objectType, null, 0);
  }

  /** Whether the object is in view. */
  public boolean found() {
    return pose != null;
  }

  @Override
  public String toString() {
    return found()
        ? String.format(Locale.ROOT, "a %s at %s, confidence %.2f", objectType, pose, confidence)
        : "no " + objectType;
  }
}
