package dev.trade.internal.codec;

/** Syntax checks for the class names that appear in encoded values. */
final class TypeNames {
  /** The JVM's limit on array dimensions. */
  static final int MAX_DIMENSIONS = 255;

  private TypeNames() {}

  /**
   * Whether {@code name} is a well-formed {@linkplain Class#getName() binary class name}: dotted Java
   * identifiers ({@code com.acme.Outer$Inner}), or an array name such as {@code [I} or
   * {@code [[Lcom.acme.Pose;}. Primitive type names are not covered.
   */
  static boolean isValid(String name) {
    if (name.isEmpty() || name.charAt(0) != '[') {
      return isBinaryName(name, 0, name.length());
    }
    int dims = 0;
    while (dims < name.length() && name.charAt(dims) == '[') {
      dims++;
    }
    if (dims > MAX_DIMENSIONS || dims == name.length()) {
      return false;
    }
    char kind = name.charAt(dims);
    if (dims + 1 == name.length()) {
      return "ZBCSIJFD".indexOf(kind) >= 0;
    }
    return kind == 'L' && name.endsWith(";") && isBinaryName(name, dims + 1, name.length() - 1);
  }

  private static boolean isBinaryName(String s, int from, int to) {
    boolean segmentStart = true;
    for (int i = from; i < to; i++) {
      char c = s.charAt(i);
      if (c == '.') {
        if (segmentStart) {
          return false; // empty segment
        }
        segmentStart = true;
      } else if (segmentStart ? Character.isJavaIdentifierStart(c) : Character.isJavaIdentifierPart(c)) {
        segmentStart = false;
      } else {
        return false;
      }
    }
    return !segmentStart; // not empty and not ending in '.'
  }
}
