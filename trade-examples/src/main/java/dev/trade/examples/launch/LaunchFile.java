package dev.trade.examples.launch;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A parsed launch file: the components of a system, each run in a JVM of its own, when to start
 * them and when to kill them. Immutable.
 *
 * <p>One directive per line. Words are separated by blanks; double quotes group words into one
 * ({@code after=planner:"waiting for navigation"}); {@code #} at the start of a word starts a
 * comment.
 *
 * <pre>
 * deadline 45s                        # optional: after this long, stop everything and fail
 * properties demo.properties          # optional: the trade.properties of every component
 * java-options -Xmx64m                # optional: JVM options of every component
 * classpath lib/*.jar build/classes   # optional: class path entries of every component
 * component NAME [OPTION...] -- MAIN-CLASS [ARGUMENT...]
 * </pre>
 *
 * Component options:
 *
 * <ul>
 *   <li>{@code after=EVENT}: start when EVENT has happened (default: at once);
 *   <li>{@code delay=DURATION}: start this long after that;
 *   <li>{@code kill-after=EVENT} or {@code kill-after=DURATION}: kill the process (SIGKILL, no
 *       shutdown hooks: a crash) when EVENT happens, or this long after it started;
 *   <li>{@code exit}: the launch ends when this component exits, with its exit status.
 * </ul>
 *
 * An EVENT is {@code NAME} (that component has been started) or {@code NAME:TEXT} (it has printed
 * a line containing TEXT). A DURATION is a whole number with {@code ms} or {@code s}. Relative
 * paths are relative to the launch file's directory.
 */
public final class LaunchFile {
  private static final Pattern NAME = Pattern.compile("[A-Za-z][A-Za-z0-9_.-]*");
  private static final Pattern DURATION = Pattern.compile("(\\d{1,9})(ms|s)");

  /**
   * Something a component waits for.
   *
   * @param component the component it happens to
   * @param text null for "has been started", else a text its output must contain
   */
  public record Event(String component, String text) {
    public Event {
      Objects.requireNonNull(component, "component == null");
    }

    /** Whether {@code line}, printed by {@code from}, is this event. */
    public boolean matches(String from, String line) {
      return text != null && component.equals(from) && line.contains(text);
    }

    @Override
    public String toString() {
      return text == null ? component + " started" : component + " printed \"" + text + "\"";
    }
  }

  /**
   * One component of the launch.
   *
   * @param after when to start it; null: at once
   * @param killWhen when to kill it; null: never, or after {@code killAfter}
   * @param killAfter how long after its start to kill it; null: never, or at {@code killWhen}
   */
  public record Component(String name, Event after, Duration delay, Event killWhen,
      Duration killAfter, boolean exit, String mainClass, List<String> arguments) {
    public Component {
      Objects.requireNonNull(name, "name == null");
      Objects.requireNonNull(delay, "delay == null");
      Objects.requireNonNull(mainClass, "mainClass == null");
      arguments = List.copyOf(arguments);
    }
  }

  private final Path file;
  private final Duration deadline;
  private final Path properties;
  private final List<String> javaOptions;
  private final List<String> classPath;
  private final List<Component> components;

  private LaunchFile(Path file, Duration deadline, Path properties, List<String> javaOptions,
      List<String> classPath, List<Component> components) {
    this.file = file;
    this.deadline = deadline;
    this.properties = properties;
    this.javaOptions = List.copyOf(javaOptions);
    this.classPath = List.copyOf(classPath);
    this.components = List.copyOf(components);
  }

  /**
   * Reads and checks a launch file.
   *
   * @throws IOException if it cannot be read
   * @throws IllegalArgumentException for a mistake in it; the message starts with
   *     {@code file:line:} and says what is expected
   */
  public static LaunchFile read(Path file) throws IOException {
    return parse(file, Files.readAllLines(file, StandardCharsets.UTF_8));
  }

  /**
   * Parses the lines of a launch file that lives at {@code file} (which need not exist).
   *
   * @throws IllegalArgumentException as {@link #read}
   */
  public static LaunchFile parse(Path file, List<String> lines) {
    Path dir = file.toAbsolutePath().getParent();
    Duration deadline = null;
    Path properties = null;
    List<String> javaOptions = new ArrayList<>();
    List<String> classPath = new ArrayList<>();
    Map<String, Component> components = new LinkedHashMap<>();
    Map<String, Integer> lineOf = new LinkedHashMap<>();
    for (int n = 1; n <= lines.size(); n++) {
      String where = file + ":" + n + ": ";
      try {
        List<String> words = words(lines.get(n - 1));
        if (words.isEmpty()) {
          continue;
        }
        List<String> rest = words.subList(1, words.size());
        switch (words.get(0)) {
          case "deadline" -> deadline = duration(single(rest, "deadline DURATION"));
          case "properties" -> properties = dir.resolve(single(rest, "properties FILE")).normalize();
          case "java-options" -> javaOptions.addAll(rest);
          case "classpath" -> {
            if (rest.isEmpty()) {
              throw new IllegalArgumentException("expected classpath ENTRY...");
            }
            // Java's own "dir/*" wildcard passes through resolve() unchanged.
            rest.forEach(entry -> classPath.add(dir.resolve(entry).normalize().toString()));
          }
          case "component" -> {
            Component c = component(rest);
            if (components.putIfAbsent(c.name(), c) != null) {
              throw new IllegalArgumentException("component '" + c.name() + "' is listed twice");
            }
            lineOf.put(c.name(), n);
          }
          default -> throw new IllegalArgumentException("unknown directive '" + words.get(0)
              + "'; expected deadline, properties, java-options, classpath or component");
        }
      } catch (IllegalArgumentException e) {
        throw new IllegalArgumentException(where + e.getMessage(), e);
      }
    }
    for (Component c : components.values()) {
      String where = file + ":" + lineOf.get(c.name()) + ": ";
      for (Event e : new Event[] {c.after(), c.killWhen()}) {
        if (e != null && !components.containsKey(e.component())) {
          throw new IllegalArgumentException(where + "no component named '" + e.component() + "'");
        }
      }
      if (startsNever(c, components, new HashSet<>())) {
        throw new IllegalArgumentException(where + "'" + c.name()
            + "' can never start: its after= events form a cycle");
      }
    }
    if (components.isEmpty()) {
      throw new IllegalArgumentException(file + ": no component");
    }
    return new LaunchFile(file, deadline, properties, javaOptions, classPath,
        new ArrayList<>(components.values()));
  }

  private static boolean startsNever(Component c, Map<String, Component> all, Set<String> seen) {
    if (c.after() == null) {
      return false;
    }
    if (!seen.add(c.name())) {
      return true;
    }
    return startsNever(all.get(c.after().component()), all, seen);
  }

  private static Component component(List<String> words) {
    int dashes = words.indexOf("--");
    if (words.isEmpty() || dashes < 1 || dashes == words.size() - 1) {
      throw new IllegalArgumentException(
          "expected: component NAME [OPTION...] -- MAIN-CLASS [ARGUMENT...]");
    }
    String name = name(words.get(0));
    Event after = null;
    Duration delay = Duration.ZERO;
    Event killWhen = null;
    Duration killAfter = null;
    boolean exit = false;
    for (String option : words.subList(1, dashes)) {
      int eq = option.indexOf('=');
      String key = eq < 0 ? option : option.substring(0, eq);
      String value = eq < 0 ? null : option.substring(eq + 1);
      switch (key) {
        case "after" -> after = event(required(key, value));
        case "delay" -> delay = duration(required(key, value));
        case "kill-after" -> {
          if (DURATION.matcher(required(key, value)).matches()) {
            killAfter = duration(value);
          } else {
            killWhen = event(value);
          }
        }
        case "exit" -> {
          if (value != null) {
            throw new IllegalArgumentException("'exit' takes no value");
          }
          exit = true;
        }
        default -> throw new IllegalArgumentException("unknown option '" + option
            + "'; expected after=, delay=, kill-after= or exit");
      }
    }
    if (after != null && after.component().equals(name)) {
      throw new IllegalArgumentException("'" + name + "' cannot start after itself");
    }
    return new Component(name, after, delay, killWhen, killAfter, exit, words.get(dashes + 1),
        words.subList(dashes + 2, words.size()));
  }

  private static Event event(String text) {
    int colon = text.indexOf(':');
    if (colon < 0) {
      return new Event(name(text), null);
    }
    if (colon == text.length() - 1) {
      throw new IllegalArgumentException("'" + text + "': the text after ':' is empty");
    }
    return new Event(name(text.substring(0, colon)), text.substring(colon + 1));
  }

  private static String name(String text) {
    if (!NAME.matcher(text).matches()) {
      throw new IllegalArgumentException("'" + text
          + "' is not a component name (a letter, then letters, digits, '_', '.' or '-')");
    }
    return text;
  }

  private static String required(String key, String value) {
    if (value == null || value.isEmpty()) {
      throw new IllegalArgumentException("'" + key + "' needs a value: " + key + "=...");
    }
    return value;
  }

  private static String single(List<String> words, String form) {
    if (words.size() != 1) {
      throw new IllegalArgumentException("expected: " + form);
    }
    return words.get(0);
  }

  /** {@code 500ms} or {@code 3s}. */
  static Duration duration(String text) {
    Matcher m = DURATION.matcher(text);
    if (!m.matches()) {
      throw new IllegalArgumentException("'" + text + "' is not a duration such as 500ms or 3s");
    }
    long n = Long.parseLong(m.group(1));
    return m.group(2).equals("s") ? Duration.ofSeconds(n) : Duration.ofMillis(n);
  }

  /** Splits a line into words: blanks separate, double quotes group, {@code #} starts a comment. */
  static List<String> words(String line) {
    List<String> words = new ArrayList<>();
    StringBuilder word = null;
    boolean quoted = false;
    for (int i = 0; i < line.length(); i++) {
      char ch = line.charAt(i);
      if (quoted) {
        if (ch == '"') {
          quoted = false;
        } else {
          word.append(ch);
        }
      } else if (Character.isWhitespace(ch)) {
        if (word != null) {
          words.add(word.toString());
          word = null;
        }
      } else if (ch == '#' && word == null) {
        break;
      } else {
        word = word == null ? new StringBuilder() : word;
        if (ch == '"') {
          quoted = true;
        } else {
          word.append(ch);
        }
      }
    }
    if (quoted) {
      throw new IllegalArgumentException("a double quote is not closed");
    }
    if (word != null) {
      words.add(word.toString());
    }
    return words;
  }

  /** The file this was read from. */
  public Path file() {
    return file;
  }

  /** How long the launch may take before everything is stopped and it fails; null: no limit. */
  public Duration deadline() {
    return deadline;
  }

  /** The absolute path of the components' trade.properties, or null. */
  public Path properties() {
    return properties;
  }

  /** JVM options for every component. */
  public List<String> javaOptions() {
    return javaOptions;
  }

  /**
   * Class path entries of every component, besides the launcher's own class path: absolute, in
   * file order.
   */
  public List<String> classPath() {
    return classPath;
  }

  /** The components, in file order. */
  public List<Component> components() {
    return components;
  }
}
