/**
 * Typed proxies: an implementation of a user's interface whose methods call the services of the
 * same name and parameter types.
 *
 * <p>{@link dev.trade.internal.proxy.Proxies} is the only entry point. Each interface method is
 * parsed once into an immutable {@code MethodModel} (the constraints that find its service, the
 * return type to call with, how its failures are thrown), cached per interface for the life of the
 * class. Each proxy holds one {@code Slot} per method: the service it resolved, replaced when
 * that service is no longer known to the container. Calls run on the caller's thread; methods
 * returning {@code CompletableFuture} find their service there and send with
 * {@code TRADEServiceInfo.callAsync}, so no thread waits for the reply.
 */
package dev.trade.internal.proxy;
