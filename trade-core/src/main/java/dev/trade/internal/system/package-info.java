/**
 * The container's own services: every container registers, when it starts, its system providers
 * (ordinary {@code @TRADEService} objects) in one reserved group, {@value
 * dev.trade.internal.system.SystemGroup#NAME}. They replicate and are found like any service, and
 * every call to them passes the providing container's host chain like any call; the static API is
 * a thin client of them.
 *
 * <p>Words: a <em>system service</em> is a service in the reserved group; an <em>ordinary
 * lookup</em> is one whose constraints do not name that group in {@code inGroups}, and it never
 * lists a system service. Users cannot register into the group. The package holds no state.
 */
package dev.trade.internal.system;
