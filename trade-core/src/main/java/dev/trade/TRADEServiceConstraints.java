package dev.trade;

import dev.trade.internal.registry.Query;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * Which services a lookup or notification is about: a mutable, fluent builder.
 *
 * <p>Each method changes {@code this} and returns it, so both {@code c.name("x").argTypes(int.class)}
 * and separate statements {@code c.name("x"); c.argTypes(int.class);} work; a later call of the
 * same method replaces the earlier value (last write wins). A service matches when it satisfies
 * every constraint that was set:
 *
 * <ul>
 *   <li>{@link #name(String)}: the method name equals the given one;
 *   <li>{@link #argTypes(Class[])}: exactly that many parameters, each declared parameter type
 *       accepting the given type (a subtype, or the boxed/primitive counterpart); {@code argTypes()}
 *       with no types means exactly zero parameters, and not calling it means any parameters;
 *   <li>{@link #returnType(Class)}: the declared return type is the given one, a subtype of it, or
 *       its boxed/primitive counterpart;
 *   <li>{@link #inGroups(String...)}: registered in all of the given groups;
 *       {@link #notInGroups(String...)}: in none of them;
 *   <li>{@link #local()}: provided by the container that performs the lookup;
 *       {@link #host(String)} (or TRADE's name {@link #onHost(String)}): provided by a container on
 *       that host; {@link #notOnHost(String...)}: by a container on none of those hosts;
 *       {@link #onLocalhost()}: by a container on the same host as the one that performs the
 *       lookup, {@link #notOnLocalhost()}: on another host. Hosts are compared by the name each
 *       container announces for itself ({@link TRADEServiceInfo#getHost()}), without any name
 *       lookup.
 * </ul>
 *
 * <p><b>Or and not.</b> Constraints form a disjunctive normal form with negation: an object matches
 * when the conjunction above matches and none of the constraints given to
 * {@link #not(TRADEServiceConstraints)} does, or when any alternative given to
 * {@link #or(TRADEServiceConstraints)} matches. A negation belongs to the conjunction of the object
 * it is added to, not to that object's alternatives:
 *
 * <pre>{@code
 * // openGripper outside group "Sim", or closeGripper in any group
 * new TRADEServiceConstraints().name("openGripper")
 *     .not(new TRADEServiceConstraints().inGroups("Sim"))
 *     .or(new TRADEServiceConstraints().name("closeGripper"));
 * }</pre>
 *
 * Alternatives and negations are copied when added (so later changes to the argument do not
 * affect this object).
 *
 * <p>Two constraints objects are {@link #equals equal} when every constraint, alternative and
 * negation is equal; since the object is mutable, so are its equality and hash code: do not change
 * one while it is a key in a hash map.
 *
 * <p>Not thread-safe: build it in one thread, then share it freely for lookups (lookups only read).
 * The class is not final, as in TRADE; a subclass that adds state should override {@link #equals}
 * and {@link #hashCode}.
 */
public class TRADEServiceConstraints {
  private String name;
  private Class<?>[] argTypes;
  private Class<?> returnType;
  private final Set<String> inGroups = new LinkedHashSet<>();
  private final Set<String> notInGroups = new LinkedHashSet<>();
  private boolean local;
  private String host;
  /** TRUE: on the looking-up container's host; FALSE: on another; null: anywhere. */
  private Boolean localhost;
  private final Set<String> notOnHosts = new LinkedHashSet<>();
  private final List<TRADEServiceConstraints> alternatives = new ArrayList<>();
  private final List<TRADEServiceConstraints> negations = new ArrayList<>();

  /** Constraints that every service matches until methods are called. */
  public TRADEServiceConstraints() {}

  /**
   * Only services with this method name.
   *
   * @param name the method name; {@code null} removes the constraint
   * @return this object
   */
  public TRADEServiceConstraints name(String name) {
    this.name = name;
    return this;
  }

  /**
   * Only services whose parameters accept exactly these types, in order. With no arguments: only
   * services without parameters. {@code argTypes((Class<?>[]) null)} removes the constraint.
   *
   * @param types the parameter types, in order
   * @return this object
   * @throws NullPointerException if one of the types is null
   */
  public TRADEServiceConstraints argTypes(Class<?>... types) {
    if (types != null) {
      for (int i = 0; i < types.length; i++) {
        Objects.requireNonNull(types[i], "argTypes[" + i + "] == null");
      }
      this.argTypes = types.clone();
    } else {
      this.argTypes = null;
    }
    return this;
  }

  /**
   * Only services whose return type fits this one.
   *
   * @param type the return type; {@code null} removes the constraint
   * @return this object
   */
  public TRADEServiceConstraints returnType(Class<?> type) {
    this.returnType = type;
    return this;
  }

  /**
   * Only services registered in every one of these groups (adds to earlier calls).
   *
   * @param groups group names; null and blank names are ignored
   * @return this object
   */
  public TRADEServiceConstraints inGroups(String... groups) {
    addGroups(inGroups, groups);
    return this;
  }

  /**
   * Only services registered in none of these groups (adds to earlier calls).
   *
   * @param groups group names; null and blank names are ignored
   * @return this object
   */
  public TRADEServiceConstraints notInGroups(String... groups) {
    addGroups(notInGroups, groups);
    return this;
  }

  /**
   * Only services of the container that performs the lookup.
   *
   * @return this object
   */
  public TRADEServiceConstraints local() {
    this.local = true;
    return this;
  }

  /**
   * Only services of containers on this host (the host name or address a container announces;
   * {@code null} removes the constraint).
   *
   * @param host the host name or address
   * @return this object
   */
  public TRADEServiceConstraints host(String host) {
    this.host = host;
    return this;
  }

  /**
   * TRADE's name for {@link #host(String)}.
   *
   * @param host the host's name, as its container announces it
   * @return this object
   */
  public TRADEServiceConstraints onHost(String host) {
    return host(host);
  }

  /**
   * Only services of containers on none of these hosts (adds to earlier calls; null and blank names
   * are ignored).
   *
   * @param hosts the hosts' names
   * @return this object
   */
  public TRADEServiceConstraints notOnHost(String... hosts) {
    addGroups(notOnHosts, hosts);
    return this;
  }

  /**
   * Only services of containers on the same host as the container that performs the lookup (its
   * own services included). Replaces an earlier {@link #notOnLocalhost()}.
   *
   * @return this object
   */
  public TRADEServiceConstraints onLocalhost() {
    this.localhost = Boolean.TRUE;
    return this;
  }

  /**
   * Only services of containers on another host than the container that performs the lookup.
   * Replaces an earlier {@link #onLocalhost()}.
   *
   * @return this object
   */
  public TRADEServiceConstraints notOnLocalhost() {
    this.localhost = Boolean.FALSE;
    return this;
  }

  /**
   * Also match services that match {@code alternative} (a copy of it is taken now).
   *
   * @param alternative other constraints; not null
   * @return this object
   */
  public TRADEServiceConstraints or(TRADEServiceConstraints alternative) {
    alternatives.add(Objects.requireNonNull(alternative, "alternative == null").copy());
    return this;
  }

  /**
   * Exclude services that match {@code excluded} from this object's own conjunction (not from its
   * alternatives); a copy of it is taken now.
   *
   * @param excluded constraints of the services to exclude; not null
   * @return this object
   */
  public TRADEServiceConstraints not(TRADEServiceConstraints excluded) {
    negations.add(Objects.requireNonNull(excluded, "excluded == null").copy());
    return this;
  }

  /**
   * A name every match must have (to narrow the scan to one name), or null when matches may have
   * any name (no name given, or alternatives that may name others).
   */
  String requiredName() {
    return alternatives.isEmpty() ? name : null;
  }

  /** An immutable snapshot for matching; later changes to this object do not affect it. */
  Query toQuery() {
    List<Query> alt = new ArrayList<>(alternatives.size());
    for (TRADEServiceConstraints a : alternatives) {
      alt.add(a.toQuery());
    }
    List<Query> neg = new ArrayList<>(negations.size());
    for (TRADEServiceConstraints n : negations) {
      neg.add(n.toQuery());
    }
    return new Query(
        name,
        argTypes == null ? null : List.of(argTypes),
        returnType,
        Set.copyOf(inGroups),
        Set.copyOf(notInGroups),
        local,
        host,
        localhost,
        Set.copyOf(notOnHosts),
        alt,
        neg);
  }

  /**
   * These constraints and, in every alternative, a service named {@code serviceName} whose
   * parameters take {@code parameterTypes}: the lookup of a proxy's method. A new object.
   */
  TRADEServiceConstraints narrowed(String serviceName, Class<?>[] parameterTypes) {
    if (alternatives.isEmpty() && name == null && argTypes == null) {
      TRADEServiceConstraints c = copy();
      c.name = serviceName;
      c.argTypes = parameterTypes.clone();
      return c;
    }
    // "A and B" as "A and not (not B)": negations are the one conjunction the model has across
    // objects, and this keeps the name required, so the lookup scans that name only.
    return new TRADEServiceConstraints().name(serviceName).argTypes(parameterTypes)
        .not(new TRADEServiceConstraints().not(this));
  }

  TRADEServiceConstraints copy() {
    TRADEServiceConstraints c = new TRADEServiceConstraints();
    c.name = name;
    c.argTypes = argTypes;
    c.returnType = returnType;
    c.inGroups.addAll(inGroups);
    c.notInGroups.addAll(notInGroups);
    c.local = local;
    c.host = host;
    c.localhost = localhost;
    c.notOnHosts.addAll(notOnHosts);
    c.alternatives.addAll(alternatives);
    c.negations.addAll(negations);
    return c;
  }

  /**
   * True when {@code o} is a constraints object of the same class with equal constraints,
   * alternatives and negations (groups and hosts compared as sets, alternatives and negations in
   * the order added).
   */
  @Override
  public boolean equals(Object o) {
    if (this == o) {
      return true;
    }
    if (o == null || o.getClass() != getClass()) {
      return false;
    }
    TRADEServiceConstraints c = (TRADEServiceConstraints) o;
    return local == c.local
        && Objects.equals(name, c.name)
        && Arrays.equals(argTypes, c.argTypes)
        && Objects.equals(returnType, c.returnType)
        && inGroups.equals(c.inGroups)
        && notInGroups.equals(c.notInGroups)
        && Objects.equals(host, c.host)
        && Objects.equals(localhost, c.localhost)
        && notOnHosts.equals(c.notOnHosts)
        && alternatives.equals(c.alternatives)
        && negations.equals(c.negations);
  }

  @Override
  public int hashCode() {
    return Objects.hash(name, Arrays.hashCode(argTypes), returnType, inGroups, notInGroups, local,
        host, localhost, notOnHosts, alternatives, negations);
  }

  private static void addGroups(Set<String> target, String[] groups) {
    if (groups == null) {
      return;
    }
    for (String g : groups) {
      if (g != null && !g.isBlank()) {
        target.add(g);
      }
    }
  }

  @Override
  public String toString() {
    StringBuilder sb = new StringBuilder("TRADEServiceConstraints{");
    String sep = "";
    if (name != null) {
      sb.append("name=").append(name);
      sep = ", ";
    }
    if (argTypes != null) {
      sb.append(sep).append("argTypes=(");
      for (int i = 0; i < argTypes.length; i++) {
        sb.append(i == 0 ? "" : ",").append(argTypes[i].getTypeName());
      }
      sb.append(')');
      sep = ", ";
    }
    if (returnType != null) {
      sb.append(sep).append("returnType=").append(returnType.getTypeName());
      sep = ", ";
    }
    if (!inGroups.isEmpty()) {
      sb.append(sep).append("inGroups=").append(inGroups);
      sep = ", ";
    }
    if (!notInGroups.isEmpty()) {
      sb.append(sep).append("notInGroups=").append(notInGroups);
      sep = ", ";
    }
    if (local) {
      sb.append(sep).append("local");
      sep = ", ";
    }
    if (host != null) {
      sb.append(sep).append("host=").append(host);
      sep = ", ";
    }
    if (!notOnHosts.isEmpty()) {
      sb.append(sep).append("notOnHost=").append(notOnHosts);
      sep = ", ";
    }
    if (localhost != null) {
      sb.append(sep).append(localhost ? "onLocalhost" : "notOnLocalhost");
      sep = ", ";
    }
    for (TRADEServiceConstraints n : negations) {
      sb.append(sep).append("not ").append(n);
      sep = ", ";
    }
    for (TRADEServiceConstraints a : alternatives) {
      sb.append(sep).append("or ").append(a);
      sep = ", ";
    }
    return sb.append('}').toString();
  }
}
