package dev.trade.internal.admin;

import dev.trade.TRADEAccess;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.system.SystemGroup;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * Which roles may call a service of this container, decided in this order: a rule of the access
 * file for the service's method name; else the rules for its groups (all of them must let the
 * caller through, so that adding a group never opens a service); else {@link TRADEAccess} on the
 * method, then on the provider's class; else the default: {@link SystemGroup#NAME} requires
 * {@link #ADMIN}, every other service is open. Immutable and thread-safe.
 */
final class Policy {
  static final String ANYONE = TRADEAccess.ANYONE;
  static final String ADMIN = "admin";

  /** What a service requires: each set is a rule that one of the caller's roles must meet. */
  record Rule(List<Set<String>> all, String source) {
    static final Rule OPEN = new Rule(List.of(), "open");

    boolean open() {
      for (Set<String> r : all) {
        if (!r.contains(ANYONE)) {
          return false;
        }
      }
      return true;
    }

    /** Whether a caller with {@code roles} passes every rule. */
    boolean allows(Set<String> roles) {
      for (Set<String> r : all) {
        if (!r.contains(ANYONE) && java.util.Collections.disjoint(r, roles)) {
          return false;
        }
      }
      return true;
    }

    /** What is missing, for the refusal: "role admin", "one of the roles a, b". */
    String required() {
      Set<String> need = new LinkedHashSet<>();
      for (Set<String> r : all) {
        if (!r.contains(ANYONE)) {
          need.addAll(r);
        }
      }
      return need.isEmpty() ? "no role" : need.size() == 1 ? "role " + need.iterator().next()
          : "one of the roles " + String.join(", ", need);
    }
  }

  private final AccessFile file;

  Policy(AccessFile file) {
    this.file = file;
  }

  Rule of(LocalService s) {
    Set<String> byName = file.serviceRule(s.descriptor().name());
    if (byName != null) {
      return new Rule(List.of(byName), "access file, service " + s.descriptor().name());
    }
    List<Set<String>> byGroups = new ArrayList<>();
    for (String g : s.descriptor().groups()) {
      Set<String> r = file.groupRule(g);
      if (r != null) {
        byGroups.add(r);
      }
    }
    if (!byGroups.isEmpty()) {
      return new Rule(byGroups, "access file, groups");
    }
    TRADEAccess a = s.method().getAnnotation(TRADEAccess.class);
    if (a == null) {
      a = s.target().getClass().getAnnotation(TRADEAccess.class);
    }
    if (a != null) {
      return new Rule(List.of(Set.of(a.value())), "@TRADEAccess");
    }
    if (s.descriptor().groups().contains(SystemGroup.NAME)) {
      return new Rule(List.of(Set.of(ADMIN)), "default of group " + SystemGroup.NAME);
    }
    return Rule.OPEN;
  }
}
