/**
 * Who exists and the next hop towards each: the replicated view of the system.
 *
 * <p>Each container owns two versioned things, its link state (the neighbours it has) and its
 * service table, and floods each change over all links; a frame that changes nothing here (a
 * version already known) is not passed on, so floods end
 * ({@link dev.trade.internal.net.mesh.FloodFilter}). A new neighbour is sent what it lacks
 * ({@link dev.trade.internal.net.mesh.Digest}). {@link dev.trade.internal.net.mesh.Routing}
 * computes shortest paths over the {@link dev.trade.internal.net.mesh.Topology} and publishes
 * the next hop to each container; tables of containers without a route wait in the
 * {@link dev.trade.internal.net.mesh.TableKeeper} until they have one.
 *
 * <p>Threads and ownership: everything here runs on the network's control thread and is owned by
 * it, except what is published for other threads as immutable snapshots (next hops, reachable
 * containers) and the staleness check made on reading threads before a frame queues. Work for
 * later comes back through a {@link dev.trade.internal.net.link.ControlScheduler}; containers
 * that become unreachable are reported to a listener, which fails their calls and tells
 * discovery.
 *
 * <p>Words: <em>flood</em> (send to every neighbour but the one it came from), <em>stale</em> (a
 * version not newer than the one known), <em>hold-down</em> (a container that became unreachable
 * stays so for a while unless it proves alive), <em>grace</em> (how long states and tables of
 * unreachable containers are kept).
 */
package dev.trade.internal.net.mesh;
