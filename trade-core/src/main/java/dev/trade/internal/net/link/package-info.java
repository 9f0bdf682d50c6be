/**
 * One authenticated connection to a neighbour container and the threads that move its frames.
 *
 * <p>A {@link dev.trade.internal.net.link.Link} exists only after its
 * {@link dev.trade.internal.net.link.Handshake} succeeded: nothing is decoded before the peer has
 * authenticated. The {@link dev.trade.internal.net.link.Connector} accepts and dials sockets and
 * runs handshakes; which of two links to one peer stays is decided by the
 * {@link dev.trade.internal.net.link.LinkReferee}, the same way at both ends.
 *
 * <p>Threads and ownership. Each link has one reading thread ({@code trade-link-PEER}) that reads
 * whole frames and gives each to its {@link dev.trade.internal.net.link.LinkHandler}; the link
 * owns its socket, its output queue and its read role, and nothing outside this package changes
 * them except through the link's methods. Any thread may send: a sender that finds the output
 * idle writes itself, else its frame is queued and whoever writes drains the queue in one system
 * call (write coalescing, {@link dev.trade.internal.net.link.LinkOutput}). The
 * {@link dev.trade.internal.net.link.Heartbeat} pings quiet links and closes silent ones from the
 * timer thread.
 *
 * <p>Words used in this package:
 * <ul>
 *   <li><em>serve here</em>: a call read on a link runs on the thread that read it; the
 *       {@link dev.trade.internal.net.link.ReadWatch} hands reading to another thread when it
 *       takes longer than a tick (<em>served elsewhere</em>).
 *   <li><em>lend</em>: a link's reading thread, having read all it holds, lets a caller waiting
 *       for its reply read the link itself; the caller <em>borrows</em> (or <em>takes</em>)
 *       reading and <em>gives it back</em> ({@link dev.trade.internal.net.link.ReadRole}).
 *   <li><em>linger</em>: how long reading stays lent after a lone caller's last call.
 *   <li><em>park</em>: a thread waits without spinning ({@code LockSupport.park}) until it is
 *       unparked or its time is up; <em>spin</em>: it waits actively, only while a reply is
 *       expected within microseconds ({@link dev.trade.internal.net.link.ReplyWait}).
 *   <li><em>retire</em>: a link that lost to a duplicate says GOODBYE after its last frame and
 *       closes; <em>hold</em>: the loss of a link waits while a handshake with its peer is under
 *       way.
 * </ul>
 *
 * <p>This package imports none of the other networking packages; they import it.
 */
package dev.trade.internal.net.link;
