/**
 * A container's networking: {@link dev.trade.internal.net.Network} composes the four packages
 * below it and owns the one piece of state they share, the map of current links.
 *
 * <ul>
 *   <li>{@code net.link}: one authenticated connection to a neighbour and its threads (handshake,
 *       connector, reading and writing, read lending, heartbeat, duplicate links).
 *   <li>{@code net.mesh}: who exists and the next hop towards each: replication of link states and
 *       service tables, and routing over them.
 *   <li>{@code net.remote}: CALL and REPLY over links: calling, forwarding, serving, deadlines.
 *   <li>{@code net.join}: which containers to link to: discovery, the overlay, the finder.
 * </ul>
 *
 * <p>Threads. The <em>control thread</em> (one per container, {@code trade-control-NAME}) applies
 * every change of state in order: links up and down, link states, tables, routes. Nothing it owns
 * is locked; other threads hand it work ({@link dev.trade.internal.net.Network#onControl}) and
 * read what it publishes through volatile snapshots (next hops, the registry's snapshot). Calls
 * and replies never wait for it: they take the fast path on the threads that read links
 * ({@link dev.trade.internal.net.FrameDispatcher}). The <em>timer</em> is the container's
 * ({@link dev.trade.internal.time.Scheduler}, handed in; this package cancels its own tasks and
 * never shuts it): it runs what must happen later (heartbeats, deadline sweeps, retries) and hands
 * state changes back to the control thread.
 *
 * <p>Layering: {@code link} imports none of its siblings; {@code mesh}, {@code remote} and
 * {@code join} import {@code link} but not one
 * another; only this package sees all four.
 */
package dev.trade.internal.net;
