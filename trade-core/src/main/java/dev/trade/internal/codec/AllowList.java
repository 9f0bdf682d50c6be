package dev.trade.internal.codec;

import dev.trade.internal.registry.Types;
import java.io.ObjectInputFilter;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The classes that decoding may load: by name for records, data classes, enums, exceptions,
 * annotations, class literals and array components, and through Java serialization. Everything that
 * no pattern allows is refused, as if the list ended in {@code !*}.
 *
 * <p>Patterns follow {@link ObjectInputFilter.Config#createFilter} syntax, without module names or
 * limits:
 *
 * <ul>
 *   <li>{@code com.acme.Pose}: exactly that class ({@code com.acme.Outer$Inner} for nested ones);
 *   <li>{@code com.acme.*}: every class in package {@code com.acme}, not in its subpackages;
 *   <li>{@code com.acme.**}: every class in {@code com.acme} and its subpackages;
 *   <li>{@code com.acme.Po*}: every class whose name starts with {@code com.acme.Po}; {@code *}
 *       allows everything;
 *   <li>{@code !pattern}: refuses what the pattern matches. Unlike {@code createFilter}, a refusal
 *       wins wherever it appears, so that it also holds against patterns added later.
 * </ul>
 *
 * <p>An array is allowed when its element type is; primitive types always are. The configuration
 * key {@value #CONFIG_KEY} holds additional patterns separated by {@code ;}.
 *
 * <p>This class is safe for concurrent use. Patterns may be added at any time (the container adds
 * the packages of registered services' parameter and return types); a check sees either all or
 * none of the patterns of one {@link #add} call.
 */
public final class AllowList {

  /** The configuration key whose value is added to the defaults. */
  public static final String CONFIG_KEY = "SERIALIZATIONALLOWLIST";

  /** JDK value packages, common JDK exceptions and the TRADE API package. */
  public static final List<String> DEFAULT_PATTERNS =
      List.of(
          "java.lang.*",
          "java.math.*",
          "java.time.*",
          "java.util.*",
          "java.util.concurrent.*",
          "java.io.IOException",
          "java.io.UncheckedIOException",
          "java.io.FileNotFoundException",
          "java.io.EOFException",
          "java.io.InterruptedIOException",
          "dev.trade.*");

  /** Copy-on-write: written under {@code this}, read without locking. */
  private volatile List<Pattern> patterns;
  /** Types whose package {@link #addPackageOf} added: a caller names its return type on every call. */
  private final Set<Class<?>> packagesAdded = ConcurrentHashMap.newKeySet();
  /** For a view made by {@link #with}: the list it extends, else null. */
  private final AllowList base;
  /** For a view made by {@link #with}: the class names it adds. */
  private final Set<String> declared;

  private AllowList(List<Pattern> patterns) {
    this.patterns = List.copyOf(patterns);
    this.base = null;
    this.declared = Set.of();
  }

  private AllowList(AllowList base, Set<String> declared) {
    this.patterns = List.of();
    this.base = base;
    this.declared = declared;
  }

  /**
   * A view that also allows the classes named exactly in {@code declared} (binary names; arrays
   * are judged by their element type as always), unless a refusal of this list matches them. The
   * view follows later changes to this list and cannot be added to itself. Used for the classes a
   * service's signature declares, in that service's calls and replies.
   */
  public AllowList with(Set<String> declared) {
    Objects.requireNonNull(declared, "declared == null");
    if (declared.isEmpty()) {
      return this;
    }
    if (base != null) {
      Set<String> both = new HashSet<>(this.declared);
      both.addAll(declared);
      return new AllowList(base, Set.copyOf(both));
    }
    return new AllowList(this, declared);
  }

  /** A list holding {@link #DEFAULT_PATTERNS}. */
  public static AllowList withDefaults() {
    AllowList list = new AllowList(List.of());
    list.add(String.join(";", DEFAULT_PATTERNS));
    return list;
  }

  /**
   * A list holding only the given {@code ;}-separated patterns (blank entries are ignored).
   *
   * @throws IllegalArgumentException if a pattern is malformed
   */
  public static AllowList of(String patterns) {
    AllowList list = new AllowList(List.of());
    list.add(patterns);
    return list;
  }

  /**
   * Adds {@code ;}-separated patterns, such as the value of {@value #CONFIG_KEY}. Blank entries are
   * ignored.
   *
   * @throws IllegalArgumentException if a pattern is malformed; then nothing is added
   */
  public void add(String patterns) {
    Objects.requireNonNull(patterns, "patterns == null");
    if (base != null) {
      throw new IllegalStateException("add patterns to the list this view was made from");
    }
    List<Pattern> parsed = new ArrayList<>();
    for (String text : patterns.split(";", -1)) {
      if (!text.isBlank()) {
        parsed.add(Pattern.parse(text.strip()));
      }
    }
    synchronized (this) {
      List<Pattern> next = new ArrayList<>(this.patterns);
      for (Pattern p : parsed) {
        if (!next.contains(p)) {
          next.add(p);
        }
      }
      this.patterns = List.copyOf(next);
    }
  }

  /**
   * Allows every class in the package of {@code type} (of its element type for arrays); does nothing
   * for primitive types.
   */
  public void addPackageOf(Class<?> type) {
    if (packagesAdded.contains(type) || !packagesAdded.add(type)) {
      return; // done before (and a read is cheaper than an insert); the patterns only grow
    }
    while (type.isArray()) {
      type = type.getComponentType();
    }
    if (!type.isPrimitive()) {
      String pkg = type.getPackageName();
      add(pkg.isEmpty() ? type.getName() : pkg + ".*");
    }
  }

  /**
   * Whether decoding may load the class with this {@linkplain Class#getName() binary name}. Array
   * names ({@code [Lcom.acme.Pose;}, {@code [I}) are judged by their element type.
   */
  public boolean isAllowed(String className) {
    String name = elementName(className);
    if (name == null) {
      return true; // a primitive type or an array of one
    }
    if (base != null) {
      int decision = base.decide(name);
      return decision > 0 || decision == 0 && declared.contains(name);
    }
    return decide(name) > 0;
  }

  /**
   * Whether a refusal ({@code !pattern}) matches the class with this binary name: such a class is
   * refused whatever else would allow it.
   */
  public boolean refuses(String className) {
    String name = elementName(className);
    return name != null && (base != null ? base : this).decide(name) < 0;
  }

  /** 1: a pattern allows {@code elementName}; -1: a refusal matches it; 0: no pattern matches. */
  private int decide(String elementName) {
    boolean allowed = false;
    for (Pattern p : patterns) {
      if (p.matches(elementName)) {
        if (p.negative) {
          return -1;
        }
        allowed = true;
      }
    }
    return allowed ? 1 : 0;
  }

  /**
   * A Java serialization filter that allows exactly the classes {@link #isAllowed} allows and
   * rejects all others. It leaves limits ({@code serialClass() == null}) undecided: combine it with
   * a limits filter. The filter follows later changes to this list.
   */
  public ObjectInputFilter filter() {
    return info -> {
      Class<?> c = info.serialClass();
      if (c == null) {
        return ObjectInputFilter.Status.UNDECIDED;
      }
      return isAllowed(c.getName())
          ? ObjectInputFilter.Status.ALLOWED
          : ObjectInputFilter.Status.REJECTED;
    };
  }

  /** The current patterns, in the order added (of the list a view was made from). */
  public List<String> patterns() {
    List<String> texts = new ArrayList<>();
    for (Pattern p : base != null ? base.patterns : patterns) {
      texts.add(p.text);
    }
    return texts;
  }

  /**
   * The patterns in {@code jdk.serialFilter} syntax, refusals first and ending in {@code !*}, for
   * use with {@link ObjectInputFilter.Config#createFilter}.
   */
  public String toFilterString() {
    if (base != null) {
      String own = base.toFilterString(); // refusals first, so the names added after stay refused
      return own.substring(0, own.length() - 2) + String.join(";", new TreeSet<>(declared))
          + ";!*";
    }
    StringBuilder sb = new StringBuilder();
    for (Pattern p : patterns) {
      if (p.negative) {
        sb.append(p.text).append(';');
      }
    }
    for (Pattern p : patterns) {
      if (!p.negative) {
        sb.append(p.text).append(';');
      }
    }
    return sb.append("!*").toString();
  }

  @Override
  public String toString() {
    return "AllowList[" + toFilterString() + "]";
  }

  /**
   * The element class name of a class or array name, or null for primitive types and arrays of
   * them. Names that are not well-formed array names are returned unchanged (and match nothing
   * sensible).
   */
  static String elementName(String className) {
    if (Types.primitive(className) != null) {
      return null;
    }
    if (!className.startsWith("[")) {
      return className;
    }
    int dims = 0;
    while (dims < className.length() && className.charAt(dims) == '[') {
      dims++;
    }
    String rest = className.substring(dims);
    if (rest.length() == 1 && "ZBCSIJFD".contains(rest)) {
      return null;
    }
    if (rest.length() > 2 && rest.charAt(0) == 'L' && rest.endsWith(";")) {
      return rest.substring(1, rest.length() - 1);
    }
    return className;
  }

  /** One parsed pattern; immutable. */
  private static final class Pattern {
    final String text;
    final boolean negative;
    /** The name, package prefix ({@code "a.b."}) or name prefix, per {@link #kind}. */
    final String body;
    /** 'E' exact, 'P' package, 'S' package and subpackages, 'R' name prefix. */
    final char kind;

    private Pattern(String text, boolean negative, String body, char kind) {
      this.text = text;
      this.negative = negative;
      this.body = body;
      this.kind = kind;
    }

    static Pattern parse(String text) {
      boolean negative = text.startsWith("!");
      String p = negative ? text.substring(1) : text;
      if (p.isEmpty() || p.contains("/") || p.contains("=") || p.chars().anyMatch(Character::isWhitespace)
          || p.indexOf('*') >= 0 && p.indexOf('*') < p.length() - (p.endsWith(".**") ? 2 : 1)) {
        throw new IllegalArgumentException(
            "bad " + CONFIG_KEY + " pattern '" + text + "': use a class name, pkg.*, pkg.** or prefix*");
      }
      if (p.endsWith(".**")) {
        return new Pattern(text, negative, p.substring(0, p.length() - 2), 'S');
      }
      if (p.endsWith(".*")) {
        return new Pattern(text, negative, p.substring(0, p.length() - 1), 'P');
      }
      if (p.endsWith("*")) {
        return new Pattern(text, negative, p.substring(0, p.length() - 1), 'R');
      }
      return new Pattern(text, negative, p, 'E');
    }

    boolean matches(String name) {
      switch (kind) {
        case 'E':
          return name.equals(body);
        case 'P':
          return name.startsWith(body) && name.indexOf('.', body.length()) < 0;
        default: // 'S' and 'R' are both prefixes
          return name.startsWith(body);
      }
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof Pattern && ((Pattern) o).text.equals(text);
    }

    @Override
    public int hashCode() {
      return text.hashCode();
    }
  }
}
