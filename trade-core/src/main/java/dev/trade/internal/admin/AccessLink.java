package dev.trade.internal.admin;

import dev.trade.TRADEException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.internal.call.CallErrors;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import java.util.Map;

import java.util.concurrent.ConcurrentHashMap;
import java.util.function.LongSupplier;

/**
 * The first link of the host chain: lets a call through when its caller's principal has a role the
 * service's {@link Policy} asks for, and refuses it otherwise with
 * {@link TRADENotAuthorizedException}, reported to the {@link AuditLog}. The principal is the one
 * the call's proof ({@link Proofs#KEY} in its context) proves; a call without one is anonymous.
 * An open service does not look at the proof at all, so ordinary calls cost one map lookup here.
 * Thread-safe.
 */
final class AccessLink implements CallLink {
  private record Cached(LocalService service, Policy.Rule rule) {}

  private final String self;
  private final String name;
  private final Registry registry;
  private final AccessFile file;
  private final Policy policy;
  private final Nonces nonces;
  private final AuditLog audit;
  private final LongSupplier millis;
  private final LongSupplier nanos;
  private final Map<Long, Cached> rules = new ConcurrentHashMap<>();
  /** Whether other containers may call this container's ordinary services (system ones: policy). */
  private volatile boolean remoteOpen = true;

  /**
   * @param millis the wall clock, milliseconds since the epoch (proofs carry the caller's)
   * @param nanos the monotonic clock the audit log's rate limit runs on
   */
  AccessLink(String self, String name, Registry registry, AccessFile file, Nonces nonces,
      AuditLog audit, LongSupplier millis, LongSupplier nanos) {
    this.self = self;
    this.name = name;
    this.registry = registry;
    this.file = file;
    this.policy = new Policy(file);
    this.nonces = nonces;
    this.audit = audit;
    this.millis = millis;
    this.nanos = nanos;
    registry.addListener((added, removed) -> removed.forEach(
        e -> rules.remove(e.descriptor().serviceId())));
  }

  @Override
  public Object proceed(Invocation call, Next next) throws TRADEException {
    ServiceDescriptor d = call.service();
    LocalService s = registry.local(d.serviceId());
    if (s == null) {
      return next.proceed(call); // the invoker says it is gone
    }
    if (!remoteOpen && !call.caller().container().toString().equals(self)
        && !d.groups().contains(SystemGroup.NAME)) {
      throw refuse(d, call.caller().container().toString(), "?", "a call from this container:"
          + " calls from other containers are switched off here (accessToTRADEServices)");
    }
    Policy.Rule rule = rule(s);
    if (rule.open()) {
      return next.proceed(call);
    }
    String proof = call.context().get(Proofs.KEY);
    String caller = call.caller().container().toString();
    if (proof == null) {
      throw refuse(d, caller, "anonymous", rule.required() + ", and the call proves no principal"
          + " (pass credentials <principal>:<secret>, or set PRINCIPAL)");
    }
    Proofs.Parsed p = Proofs.parse(proof);
    if (p == null) {
      throw refuse(d, caller, "?", "a proof of principal, and the call's proof is malformed");
    }
    AccessFile.Principal principal = file.principal(p.principal());
    if (principal == null || !Proofs.verify(p, Proofs.key(principal.name(), principal.secret()),
        caller, self, d.serviceId())) {
      // One answer for both: a guesser must not learn which principals exist.
      throw refuse(d, caller, p.principal(), rule.required() + ", and the proof of principal '"
          + p.principal() + "' is not valid (unknown principal or wrong secret)");
    }
    Nonces.Verdict v = nonces.accept(p.nonce(), p.timeMillis(), millis.getAsLong());
    if (v != Nonces.Verdict.FRESH) {
      throw refuse(d, caller, p.principal(), switch (v) {
        case REPLAYED -> "a fresh proof, and this one was used before (replayed)";
        case TOO_OLD, TOO_NEW -> "a proof made within " + nonces.windowMillis() / 1000
            + " s of this container's clock; synchronise the clocks";
        default -> "room for the proof: too many proofs within one window; try again later";
      });
    }
    if (!rule.allows(principal.roles())) {
      throw refuse(d, caller, principal.name(), rule.required() + ", and principal '"
          + principal.name() + "' has " + (principal.roles().isEmpty() ? "no roles"
          : "the roles " + String.join(", ", principal.roles())));
    }
    return next.proceed(call);
  }

  void setRemoteOpen(boolean open) {
    remoteOpen = open;
  }

  private Policy.Rule rule(LocalService s) {
    Cached c = rules.get(s.descriptor().serviceId());
    if (c == null || c.service() != s) {
      c = new Cached(s, policy.of(s));
      rules.put(s.descriptor().serviceId(), c);
    }
    return c.rule();
  }

  private TRADENotAuthorizedException refuse(ServiceDescriptor d, String caller, String principal,
      String missing) {
    TRADENotAuthorizedException e = CallErrors.notAuthorized(d, missing);
    audit.refused(d.signature() + " of container " + name + " called by container " + caller
        + " as " + principal + ": needs " + missing, nanos.getAsLong());
    return e;
  }

}
