/**
 * The middleware's own operations as services, and access control (docs/middleware-services.md,
 * docs/security.md).
 *
 * <p>{@link dev.trade.internal.admin.AdminService} is each container's system service of
 * middleware operations; {@link dev.trade.internal.admin.AdminClient} is the static API's client
 * of it. {@link dev.trade.internal.admin.Access} is access control: the access file's principals
 * and rules, the first link of the host chain that enforces them, and the proofs a caller puts in
 * a call's context.
 *
 * <p>Words: a <em>principal</em> is a name with roles and a secret, from the access file
 * ({@code PRINCIPALSFILE}); <em>credentials</em> are {@code <principal>:<secret>} given to the API
 * or as {@code PRINCIPAL}; a <em>proof</em> is the HMAC in the context entry {@code trade.auth}
 * that shows a caller knows the secret without sending it; a <em>refusal</em> is a call the access
 * link stopped, reported to the audit logger {@code dev.trade.audit}.
 *
 * <p>Threads and state: the access link runs on every calling thread; its state (replay guard,
 * audit rate limit) is guarded by one lock each, and the rest is immutable, built once from the
 * settings. The administration service keeps the providers it started, under its own lock.
 */
package dev.trade.internal.admin;
