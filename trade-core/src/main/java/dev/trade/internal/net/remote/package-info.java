/**
 * Remote calls over links: CALL and REPLY frames (docs/protocol.md).
 *
 * <p>{@link dev.trade.internal.net.remote.RemoteCalls} is the calling side (request ids, pending
 * calls, waiting for the reply), passes on frames addressed to other containers and takes
 * replies back to their callers, also when a route has just broken;
 * {@link dev.trade.internal.net.remote.CallServer} is the providing side: it decodes a CALL,
 * runs it through the {@link dev.trade.internal.call.Provider}'s host chain and answers with
 * exactly one REPLY, whatever happens, through the calls' way back;
 * {@link dev.trade.internal.net.remote.Deadlines} fails the calls whose deadline passed.
 *
 * <p>Threads: calls and replies run on the threads that read links (never on the control
 * thread), and a caller waits on its own thread; state is the map of pending calls, safe for
 * concurrent use. Every remote call has a deadline, carried in its CALL frame; a call fails at
 * most one sweep tick after it.
 */
package dev.trade.internal.net.remote;
