package dev.trade.internal.admin;

import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.CallLink;
import dev.trade.internal.config.Settings;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * A container's access control, both halves: the {@link #link() host chain's first link}, which
 * enforces the policy on calls to this container's services, and the proofs this container puts
 * on the calls it makes ({@link #context}). Built once from the settings; safe for concurrent use.
 */
public final class Access {
  /** How far a proof's time may be from the provider's clock, either way. */
  static final long WINDOW_MILLIS = 30_000;
  /** The most proofs remembered within one window. */
  static final int MAX_NONCES = 100_000;
  /** Refusals logged per window of the audit log's rate limit. */
  static final int AUDIT_LINES = 10;
  static final long AUDIT_WINDOW_NANOS = TimeUnit.SECONDS.toNanos(10);

  private final String self;
  private final Credentials own;
  /** The key of {@link #own}, derived once: every call this container makes proves it. */
  private final byte[] ownKey;
  private final AccessLink link;

  private Access(String self, Credentials own, AccessLink link) {
    this.self = self;
    this.own = own;
    this.ownKey = own.isAnonymous() ? null : Proofs.key(own.principal(), own.secret());
    this.link = link;
  }

  /**
   * Reads {@code PRINCIPALSFILE} and {@code PRINCIPAL}.
   *
   * @throws IllegalArgumentException naming the file and line of a bad access file, or PRINCIPAL
   *     when it is not {@code <principal>:<secret>}
   */
  public static Access of(Settings settings, String self, String name, Registry registry) {
    AccessFile file = settings.principalsFile().isEmpty() ? AccessFile.EMPTY
        : AccessFile.load(Path.of(settings.principalsFile()));
    Credentials own;
    try {
      own = Credentials.parse(settings.principal());
    } catch (IllegalArgumentException e) {
      throw new IllegalArgumentException("PRINCIPAL=****: " + e.getMessage(), e);
    }
    if (!settings.principal().isEmpty() && own.isAnonymous()) {
      throw new IllegalArgumentException("PRINCIPAL=****: expected <principal>:<secret>");
    }
    AccessLink link = new AccessLink(self, name, registry, file,
        new Nonces(WINDOW_MILLIS, MAX_NONCES),
        new AuditLog(System.getLogger(AuditLog.NAME), AUDIT_LINES, AUDIT_WINDOW_NANOS),
        System::currentTimeMillis, System::nanoTime);
    return new Access(self, own, link);
  }

  /** Lets other containers call this container's ordinary services, or stops them. */
  public void setRemoteAccess(boolean open) {
    link.setRemoteOpen(open);
  }

  /** The first link of the host chain. */
  public CallLink link() {
    return link;
  }

  /**
   * The context of a call from this container to {@code d} as {@code credentials}: a proof, or
   * empty when they are anonymous.
   */
  public CallContext context(Credentials credentials, ServiceDescriptor d) {
    if (credentials.isAnonymous()) {
      return CallContext.EMPTY;
    }
    return CallContext.of(Map.of(Proofs.KEY, Proofs.sign(credentials, self, d.containerId(),
        d.serviceId(), System.currentTimeMillis())));
  }

  /** The context of a call this container makes on its own behalf ({@code PRINCIPAL}). */
  public CallContext ownContext(ServiceDescriptor d) {
    if (ownKey == null) {
      return CallContext.EMPTY;
    }
    return CallContext.of(Map.of(Proofs.KEY, Proofs.sign(own.principal(), ownKey, self,
        d.containerId(), d.serviceId(), System.currentTimeMillis(), Proofs.nonce())));
  }
}
