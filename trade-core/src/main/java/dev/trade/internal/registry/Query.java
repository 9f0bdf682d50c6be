package dev.trade.internal.registry;

import dev.trade.internal.system.SystemGroup;
import java.util.List;
import java.util.Set;

/**
 * An immutable snapshot of a {@code TRADEServiceConstraints}: a conjunction of constraints, minus
 * the negations, or any of the alternatives. A system service (reserved group) matches only a query
 * whose {@code inGroups} names that group. Thread-safe.
 *
 * @param name method name, or null for any
 * @param argTypes exact parameter count and accepted types, or null for any
 * @param returnType accepted return type, or null for any
 * @param inGroups groups the service must all be in
 * @param notInGroups groups the service must not be in
 * @param local only services of the looking-up container
 * @param host only services on this host, or null for any
 * @param localhost TRUE: only services on the looking-up container's host; FALSE: only on other
 *     hosts; null: any
 * @param notOnHosts hosts the service must not be on
 * @param alternatives other queries, any of which also matches
 * @param negations queries that must not match
 */
public record Query(
    String name,
    List<Class<?>> argTypes,
    Class<?> returnType,
    Set<String> inGroups,
    Set<String> notInGroups,
    boolean local,
    String host,
    Boolean localhost,
    Set<String> notOnHosts,
    List<Query> alternatives,
    List<Query> negations) {

  public Query {
    alternatives = List.copyOf(alternatives);
    negations = List.copyOf(negations);
  }

  /**
   * Whether the entry matches, as seen by the container with id {@code localContainerId} on host
   * {@code localHost}.
   */
  public boolean matches(Entry e, String localContainerId, String localHost) {
    if (matchesOwn(e, localContainerId, localHost)) {
      boolean excluded = false;
      for (Query n : negations) {
        if (n.matches(e, localContainerId, localHost)) {
          excluded = true;
          break;
        }
      }
      if (!excluded) {
        return true;
      }
    }
    for (Query a : alternatives) {
      if (a.matches(e, localContainerId, localHost)) {
        return true;
      }
    }
    return false;
  }

  private boolean matchesOwn(Entry e, String localContainerId, String localHost) {
    ServiceDescriptor d = e.descriptor();
    if (name != null && !name.equals(d.name())) {
      return false;
    }
    if (local && !d.containerId().equals(localContainerId)) {
      return false;
    }
    if (host != null && !host.equals(d.host())) {
      return false;
    }
    if (localhost != null && localhost != localHost.equals(d.host())) {
      return false;
    }
    if (notOnHosts.contains(d.host())) {
      return false;
    }
    if (!d.groups().containsAll(inGroups) || SystemGroup.hides(d.groups(), inGroups)) {
      return false;
    }
    for (String g : notInGroups) {
      if (d.groups().contains(g)) {
        return false;
      }
    }
    if (argTypes != null && !argTypesMatch(e)) {
      return false;
    }
    return returnType == null || returnTypeMatches(e);
  }

  private boolean argTypesMatch(Entry e) {
    List<String> declared = e.descriptor().parameterTypeNames();
    if (declared.size() != argTypes.size()) {
      return false;
    }
    for (int i = 0; i < argTypes.size(); i++) {
      Class<?> given = argTypes.get(i);
      Class<?> p = e.parameterType(i, given.getClassLoader());
      if (p == null
          ? !Types.box(given).getTypeName().equals(boxedName(declared.get(i)))
          : !Types.accepts(p, given)) {
        return false;
      }
    }
    return true;
  }

  private boolean returnTypeMatches(Entry e) {
    Class<?> declared = e.returnType(returnType.getClassLoader());
    if (declared == null) {
      return returnType.getTypeName().equals(e.descriptor().returnTypeName());
    }
    if (declared == void.class || returnType == void.class || returnType == Void.class) {
      return Types.box(declared) == Types.box(returnType);
    }
    return Types.accepts(returnType, declared);
  }

  private static String boxedName(String typeName) {
    Class<?> c = Types.resolve(typeName, null);
    return c != null && c.isPrimitive() ? Types.box(c).getTypeName() : typeName;
  }
}
