/**
 * Locks over sets of services: the lease table of the services a container provides, the link of
 * its host chain that enforces it, the system service {@code LockService} through which every
 * container (and any client that can call services) locks, renews, releases and lists, and the
 * client behind the static API that takes a set of services in many containers at once.
 *
 * <p>Words: a <em>lock</em> has a random id and is <em>owned</em> by the container that took it
 * (the CALL's source, never a claim in an argument). In each container that provides some of its
 * services it holds a <em>lease</em>: the services, the owner, and an expiry that the owner's
 * renewals push forward; a lease whose expiry passed is gone, as if released. Each service a lease
 * holds has a <em>fencing token</em>, taken from a counter of the providing container, so tokens
 * increase per service with every grant; a call carries the lock id and the token of the service,
 * and the host chain refuses a token older than the service's latest grant. A <em>waiter</em> is a
 * lock request queued until its services are free; its <em>ticket</em> orders the queue of every
 * service it waits for, which makes granting first come, first served per service and free of
 * cycles inside one container. Across containers a client takes containers in one global order
 * (container id, then service id) and releases what it took when one refuses.
 *
 * <p>Threads: the table is guarded by its own monitor; waiting lock requests and waiting calls wait
 * on it, woken by every release and at the next expiry. Every decision that depends on time takes
 * {@code now} ({@link System#nanoTime()} units) as a parameter; only the service and the link read
 * the clock they are given. The client renews its leases from one daemon thread per container.
 */
package dev.trade.internal.lock;
