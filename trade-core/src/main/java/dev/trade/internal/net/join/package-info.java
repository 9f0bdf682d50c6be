/**
 * Which containers to link to: announcing this container, hearing others, and choosing whom to
 * dial.
 *
 * <p>The {@link dev.trade.internal.net.join.Finder} holds the switches (announce, discover,
 * listen), starts multicast discovery ({@code dev.trade.internal.discovery}) when first switched
 * on, keeps the set of live containers it hears and dials the ones the
 * {@link dev.trade.internal.net.join.Overlay} chooses: all in a small system, a ring with
 * fingers in a large one. Links that exist are never closed here.
 *
 * <p>Threads: announcements arrive on discovery's receiving thread, decisions that depend on
 * time run on the container's timer and take {@code now} from its clock; state is guarded by
 * each object's lock. Words: <em>hold</em> (a newcomer keeps its first choice until it has heard the system),
 * <em>forget</em> (routing found a container unreachable: stop counting it).
 */
package dev.trade.internal.net.join;
