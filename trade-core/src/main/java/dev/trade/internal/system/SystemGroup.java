package dev.trade.internal.system;

import dev.trade.TRADERegistrationException;
import java.util.Collection;
import java.util.Set;

/**
 * The reserved group of system services, and the two rules that keep it apart: ordinary lookups do
 * not see it, and users cannot register into it. Stateless.
 */
public final class SystemGroup {
  /**
   * The reserved group's name. Constraints with {@code inGroups("trade.system")} find system
   * services; constraints without it never do.
   */
  public static final String NAME = "trade.system";

  private SystemGroup() {}

  /**
   * Refuses a user's registration into the reserved group.
   *
   * @throws TRADERegistrationException if {@code groups} contains {@link #NAME}
   */
  public static void refuse(Collection<String> groups) throws TRADERegistrationException {
    if (groups.contains(NAME)) {
      throw new TRADERegistrationException("Group '" + NAME + "' is reserved for the container's own"
          + " services (notifications and other middleware operations); register in another group");
    }
  }

  /**
   * Whether a service in {@code serviceGroups} is hidden from a lookup that asks for
   * {@code inGroups}: system services match only constraints that name the reserved group, so
   * users' lists (and DIARC's) stay as they were before system services existed.
   */
  public static boolean hides(Set<String> serviceGroups, Set<String> inGroups) {
    return serviceGroups.contains(NAME) && !inGroups.contains(NAME);
  }
}
