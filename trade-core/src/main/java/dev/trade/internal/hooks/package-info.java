/**
 * Before and after hooks (docs/hooks.md): a service, the <em>wrapper</em>, called before or after
 * every call of another, its <em>target</em>, from wherever the call comes.
 *
 * <p>{@link dev.trade.internal.hooks.HookTable} holds the hooks on this container's services,
 * copy-on-write: it is resolved when a hook is added or removed, never per call.
 * {@link dev.trade.internal.hooks.HookLink} is the host chain's link that calls them (after access
 * and locks, so hooks see only calls that will run); {@link dev.trade.internal.hooks.HookService}
 * is this container's system service that adds, removes and lists them;
 * {@link dev.trade.internal.hooks.HookClient} is the requester's side behind the static API, which
 * reaches a table only through that service and keeps set hooks (hooks on every service matching
 * constraints, also those that join later). {@link dev.trade.internal.hooks.HookPath} carries the
 * hooks already running on a call's path, on the thread and in the call context, so that no hook
 * runs inside its own call.
 *
 * <p>Threads: synchronous hooks run on the calling thread, but for local wrappers, which run on
 * {@link dev.trade.internal.hooks.LocalWrappers}' threads while the call waits for them up to the
 * hook timeout; asynchronous after hooks on the link's
 * pool (two threads, made at first use); set hooks reach services that join on the client's one
 * thread. Words: a hook <em>fails</em> when its wrapper throws, times out or cannot be called; a
 * failure is counted and logged and never reaches the call.
 */
package dev.trade.internal.hooks;
