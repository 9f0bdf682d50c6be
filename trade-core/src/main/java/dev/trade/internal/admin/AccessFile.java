package dev.trade.internal.admin;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * The access file named by {@code PRINCIPALSFILE}: the principals (name, roles, secret) and the
 * policy rules (which roles may call a service name or a group). The format, one entry a line
 * (docs/security.md):
 *
 * <pre>
 * # comment
 * principal &lt;name&gt; &lt;role,role,...|-&gt; &lt;secret&gt;
 * allow service &lt;method name&gt; &lt;role,role,...|*&gt;
 * allow group &lt;group&gt; &lt;role,role,...|*&gt;
 * </pre>
 *
 * A bad line fails the whole file with an error naming the file and the line (never the secret).
 * Immutable and safe for concurrent use.
 */
final class AccessFile {
  /** Names of principals and roles: what can travel in a proof and appear in a log line. */
  static final Pattern NAME = Pattern.compile("[A-Za-z0-9._-]{1,64}");
  /** The smallest secret accepted: shorter ones are guessed too easily. */
  static final int MIN_SECRET = 8;

  static final AccessFile EMPTY = new AccessFile(Map.of(), Map.of(), Map.of());

  /** A principal: its name, its roles and the secret that proves it. */
  record Principal(String name, Set<String> roles, String secret) {
    Principal {
      roles = Set.copyOf(roles);
    }

    @Override
    public String toString() {
      return "Principal[" + name + ", roles " + roles + "]"; // never the secret
    }
  }

  private final Map<String, Principal> principals;
  private final Map<String, Set<String>> services;
  private final Map<String, Set<String>> groups;

  private AccessFile(Map<String, Principal> principals, Map<String, Set<String>> services,
      Map<String, Set<String>> groups) {
    this.principals = Map.copyOf(principals);
    this.services = Map.copyOf(services);
    this.groups = Map.copyOf(groups);
  }

  /**
   * Reads the file at {@code path}.
   *
   * @throws IllegalArgumentException naming the file and the line of the first bad line, or the
   *     file when it cannot be read
   */
  static AccessFile load(Path path) {
    List<String> lines;
    try {
      lines = Files.readAllLines(path, StandardCharsets.UTF_8);
    } catch (IOException e) {
      throw new IllegalArgumentException("PRINCIPALSFILE=" + path + ": cannot be read ("
          + e.getMessage() + "); name a readable access file (docs/security.md)", e);
    }
    return parse(String.valueOf(path), lines);
  }

  /**
   * Parses the lines of an access file named {@code source} (for messages).
   *
   * @throws IllegalArgumentException naming the source and the line of the first bad line
   */
  static AccessFile parse(String source, List<String> lines) {
    Map<String, Principal> principals = new LinkedHashMap<>();
    Map<String, Set<String>> services = new LinkedHashMap<>();
    Map<String, Set<String>> groups = new LinkedHashMap<>();
    for (int i = 0; i < lines.size(); i++) {
      String line = lines.get(i).strip();
      if (line.isEmpty() || line.startsWith("#")) {
        continue;
      }
      String[] f = line.split("\\s+");
      String where = "access file " + source + ", line " + (i + 1) + ": ";
      if (f[0].equals("principal")) {
        if (f.length != 4) {
          throw new IllegalArgumentException(where + "expected 'principal <name> <roles|-> <secret>'"
              + " (4 fields separated by spaces; the secret has no spaces), found " + f.length
              + " fields");
        }
        String name = name(where, "principal name", f[1]);
        if (principals.containsKey(name)) {
          throw new IllegalArgumentException(where + "principal '" + name + "' is defined twice;"
              + " keep one line per principal");
        }
        Set<String> roles = f[2].equals("-") ? Set.of() : roles(where, f[2], false);
        if (f[3].length() < MIN_SECRET) {
          throw new IllegalArgumentException(where + "the secret of principal '" + name
              + "' is shorter than " + MIN_SECRET + " characters; use a long random secret");
        }
        principals.put(name, new Principal(name, roles, f[3]));
      } else if (f[0].equals("allow")) {
        if (f.length != 4 || !(f[1].equals("service") || f[1].equals("group"))) {
          throw new IllegalArgumentException(where + "expected 'allow service <name> <roles|*>' or"
              + " 'allow group <group> <roles|*>'");
        }
        Map<String, Set<String>> target = f[1].equals("service") ? services : groups;
        if (target.containsKey(f[2])) {
          throw new IllegalArgumentException(where + f[1] + " '" + f[2] + "' has a rule already;"
              + " keep one rule per " + f[1]);
        }
        target.put(f[2], roles(where, f[3], true));
      } else {
        throw new IllegalArgumentException(where + "unknown entry '" + f[0] + "'; a line is a"
            + " comment (#), 'principal ...' or 'allow ...'");
      }
    }
    return new AccessFile(principals, services, groups);
  }

  private static String name(String where, String what, String s) {
    if (!NAME.matcher(s).matches()) {
      throw new IllegalArgumentException(where + "'" + s + "' is not a " + what + ": 1 to 64 of"
          + " A-Z a-z 0-9 . _ -");
    }
    return s;
  }

  private static Set<String> roles(String where, String list, boolean anyoneAllowed) {
    Set<String> roles = new LinkedHashSet<>();
    for (String r : Arrays.asList(list.split(","))) {
      if (anyoneAllowed && r.equals(Policy.ANYONE)) {
        roles.add(r);
      } else {
        roles.add(name(where, "role", r));
      }
    }
    return roles;
  }

  /** The principal named {@code name}, or null. */
  Principal principal(String name) {
    return principals.get(Objects.requireNonNull(name));
  }

  /** The roles the file allows for services of this method name, or null when it has no rule. */
  Set<String> serviceRule(String name) {
    return services.get(name);
  }

  /** The roles the file allows for services of this group, or null when it has no rule. */
  Set<String> groupRule(String group) {
    return groups.get(group);
  }

  int principalCount() {
    return principals.size();
  }

  @Override
  public String toString() {
    return "AccessFile[" + principals.size() + " principals, " + services.size()
        + " service rules, " + groups.size() + " group rules]";
  }
}
