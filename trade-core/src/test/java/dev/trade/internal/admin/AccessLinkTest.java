package dev.trade.internal.admin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEAccess;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEService;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.Caller;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.registry.LocalService;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The access link on its own: proofs, replays, roles and the audit log, on fake clocks. */
class AccessLinkTest {
  private static final String SELF = UUID.randomUUID().toString();
  private static final UUID CALLER = UUID.randomUUID();
  private static final AccessFile FILE = AccessFile.parse("test", List.of(
      "principal alice admin alice-secret-1",
      "principal bob operator bob-secret-22",
      "allow group lab operator"));

  public static final class Ops {
    @TRADEService
    public String shutdown() {
      return "ran";
    }
  }

  public static final class Arm {
    @TRADEService
    public String move() {
      return "ran";
    }

    @TRADEService
    @TRADEAccess("admin")
    public String calibrate() {
      return "ran";
    }
  }

  private final AtomicLong millis = new AtomicLong(1_700_000_000_000L);
  private final AtomicLong nanos = new AtomicLong();
  private final AuditLogTest.Recording log = new AuditLogTest.Recording();
  private Registry registry;
  private AccessLink link;

  @BeforeEach
  void setUp() {
    registry = new Registry(SELF, "robot", "host");
    link = new AccessLink(SELF, "robot", registry, FILE, new Nonces(30_000, 1000),
        new AuditLog(log, 10, 10_000_000_000L), millis::get, nanos::get);
  }

  private ServiceDescriptor service(Object provider, String name, String... groups)
      throws Exception {
    for (LocalService s : registry.register(provider, Set.of(groups))) {
      if (s.descriptor().name().equals(name)) {
        return s.descriptor();
      }
    }
    throw new AssertionError(name);
  }

  private Object call(ServiceDescriptor d, CallContext context) throws Exception {
    return link.proceed(new Invocation(d, new Object[0], 0, new Caller(CALLER, ""), context),
        call -> "ran");
  }

  private CallContext proof(String credentials, ServiceDescriptor d) {
    return CallContext.of(Map.of(Proofs.KEY, Proofs.sign(Credentials.parse(credentials),
        CALLER.toString(), SELF, d.serviceId(), millis.get())));
  }

  @Test
  void systemServicesNeedAdminOrdinaryOnesAreOpen() throws Exception {
    ServiceDescriptor shutdown = service(new Ops(), "shutdown", "trade.system");
    ServiceDescriptor move = service(new Arm(), "move");
    assertEquals("ran", call(move, CallContext.EMPTY));
    TRADENotAuthorizedException e = assertThrows(TRADENotAuthorizedException.class,
        () -> call(shutdown, CallContext.EMPTY));
    assertEquals("Not authorized: shutdown() of container robot needs role admin, and the call"
        + " proves no principal (pass credentials <principal>:<secret>, or set PRINCIPAL)",
        e.getMessage());
    assertEquals("ran", call(shutdown, proof("alice:alice-secret-1", shutdown)));
    e = assertThrows(TRADENotAuthorizedException.class,
        () -> call(shutdown, proof("bob:bob-secret-22", shutdown)));
    assertEquals("Not authorized: shutdown() of container robot needs role admin, and principal"
        + " 'bob' has the roles operator", e.getMessage());
  }

  @Test
  void annotationAndAccessFileRules() throws Exception {
    ServiceDescriptor calibrate = service(new Arm(), "calibrate", "lab");
    // The access file's group rule (operator) wins over the annotation (admin).
    assertEquals("ran", call(calibrate, proof("bob:bob-secret-22", calibrate)));
    assertThrows(TRADENotAuthorizedException.class,
        () -> call(calibrate, proof("alice:alice-secret-1", calibrate)));
    Registry other = new Registry(SELF, "robot", "host");
    AccessLink plain = new AccessLink(SELF, "robot", other, AccessFile.EMPTY,
        new Nonces(30_000, 10), new AuditLog(log, 10, 1), millis::get, nanos::get);
    ServiceDescriptor annotated = null;
    for (LocalService s : other.register(new Arm(), Set.of())) {
      if (s.descriptor().name().equals("calibrate")) {
        annotated = s.descriptor();
      }
    }
    ServiceDescriptor d = annotated;
    TRADENotAuthorizedException e = assertThrows(TRADENotAuthorizedException.class,
        () -> plain.proceed(new Invocation(d, new Object[0], 0, new Caller(CALLER, ""),
            CallContext.EMPTY), call -> "ran"));
    assertTrue(e.getMessage().contains("needs role admin"), e.getMessage());
  }

  @Test
  void forgedReplayedAndStaleProofsAreRefused() throws Exception {
    ServiceDescriptor shutdown = service(new Ops(), "shutdown", "trade.system");
    TRADENotAuthorizedException e = assertThrows(TRADENotAuthorizedException.class,
        () -> call(shutdown, proof("alice:guessed-secret", shutdown)));
    assertEquals("Not authorized: shutdown() of container robot needs role admin, and the proof of"
        + " principal 'alice' is not valid (unknown principal or wrong secret)", e.getMessage());
    assertFalse(e.getMessage().contains("alice-secret-1"));

    CallContext once = proof("alice:alice-secret-1", shutdown);
    assertEquals("ran", call(shutdown, once));
    e = assertThrows(TRADENotAuthorizedException.class, () -> call(shutdown, once));
    assertTrue(e.getMessage().endsWith("needs a fresh proof, and this one was used before"
        + " (replayed)"), e.getMessage());

    // A proof made for another service, or by another caller, does not verify.
    ServiceDescriptor move = service(new Arm(), "move");
    CallContext forOther = proof("alice:alice-secret-1", move);
    e = assertThrows(TRADENotAuthorizedException.class, () -> call(shutdown, forOther));
    assertTrue(e.getMessage().contains("is not valid"), e.getMessage());

    CallContext old = proof("alice:alice-secret-1", shutdown);
    millis.addAndGet(30_001);
    e = assertThrows(TRADENotAuthorizedException.class, () -> call(shutdown, old));
    assertTrue(e.getMessage().contains("within 30 s of this container's clock"), e.getMessage());

    e = assertThrows(TRADENotAuthorizedException.class, () -> call(shutdown,
        CallContext.of(Map.of(Proofs.KEY, "1 alice 12 zz"))));
    assertTrue(e.getMessage().contains("malformed"), e.getMessage());
  }

  @Test
  void aGuesserGetsOnlyRefusalsAndTheLogIsRateLimited() throws Exception {
    ServiceDescriptor shutdown = service(new Ops(), "shutdown", "trade.system");
    int refused = 0;
    for (int i = 0; i < 500; i++) {
      String guess = "alice:guess-" + i;
      try {
        call(shutdown, proof(guess, shutdown));
      } catch (TRADENotAuthorizedException e) {
        refused++;
        assertFalse(e.getMessage().contains("alice-secret-1"));
      }
    }
    assertEquals(500, refused);
    assertEquals(10, log.lines.size(), "at most 10 lines per window");
    assertTrue(log.lines.get(0).startsWith("WARNING refused: shutdown() of container robot called"
        + " by container " + CALLER + " as alice: needs role admin"), log.lines.get(0));
    nanos.addAndGet(10_000_000_000L);
    assertThrows(TRADENotAuthorizedException.class, () -> call(shutdown, CallContext.EMPTY));
    assertEquals("WARNING 490 more refusals were not logged (at most 10 are logged per 10 s)",
        log.lines.get(10));
  }
}
