package org.example.proxy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceNotFoundException;
import dev.trade.UncheckedTRADEException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Typed proxies, from outside the library's package, as users write them. */
class ProxyTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** Thrown by the provider, declared by the interface. */
  public static class JammedException extends Exception {
    private static final long serialVersionUID = 1L;

    public JammedException(String message) {
      super(message);
    }
  }

  public static class Gripper {
    private final String who;

    public Gripper(String who) {
      this.who = who;
    }

    @TRADEService
    public String grip(int force) {
      return who + " grips " + force;
    }

    @TRADEService
    public String grip(String how) {
      return who + " grips " + how;
    }

    @TRADEService
    public void release() throws JammedException {
      throw new JammedException(who + " is jammed");
    }

    @TRADEService
    public List<String> fingers() {
      return List.of("left", "right");
    }
  }

  public interface Checked {
    String grip(int force) throws TRADEException;

    String grip(String how) throws TRADEException;

    void release() throws JammedException, TRADEException;

    List<String> fingers() throws TRADEException;

    CompletableFuture<String> grip(long force);

    default String twice(int force) throws TRADEException {
      return grip(force) + ", " + grip(force);
    }
  }

  public interface Unchecked {
    String grip(int force);

    void release();

    boolean missing(String x);

    CompletableFuture<Boolean> missingLater();
  }

  public interface Async {
    CompletableFuture<String> grip(int force);
  }

  private final TRADEContainer c = TRADEContainer.builder().name("proxies").build();

  @AfterEach
  void close() {
    c.close();
  }

  @Test
  void methodsCallTheServiceOfTheirNameAndParameterTypes() throws Exception {
    c.registerAllServices(new Gripper("g"), "arm");
    Checked p = c.proxy(Checked.class);

    assertEquals("g grips 3", p.grip(3));
    assertEquals("g grips firmly", p.grip("firmly"));
    assertEquals(List.of("left", "right"), p.fingers());
    assertEquals("g grips 2, g grips 2", p.twice(2));
    assertTrue(p.toString().contains(Checked.class.getName()), p.toString());
    assertEquals(p, p);
  }

  @Test
  void futuresCompleteWithTheResult() throws Exception {
    c.registerAllServices(new Gripper("g"), "arm");
    Async p = c.proxy(Async.class);
    assertEquals("g grips 5", p.grip(5).get(10, TimeUnit.SECONDS));
  }

  @Test
  void failuresAreTheDeclaredTypesOrWrapTheTypedCause() throws Exception {
    c.registerAllServices(new Gripper("g"), "arm");
    JammedException jammed = assertThrows(JammedException.class, () -> c.proxy(Checked.class).release());
    assertEquals("g is jammed", jammed.getMessage());

    Unchecked u = c.proxy(Unchecked.class);
    UncheckedTRADEException e = assertThrows(UncheckedTRADEException.class, u::release);
    assertInstanceOf(JammedException.class, e.getCause().getCause());
    e = assertThrows(UncheckedTRADEException.class, () -> u.missing("x"));
    assertInstanceOf(TRADEServiceNotFoundException.class, e.getCause());
    assertTrue(e.getMessage().contains("name=missing"), e.getMessage());

    ExecutionException later = assertThrows(ExecutionException.class,
        () -> u.missingLater().get(10, TimeUnit.SECONDS));
    assertInstanceOf(UncheckedTRADEException.class, later.getCause());
    assertInstanceOf(TRADEServiceNotFoundException.class, later.getCause().getCause());
  }

  @Test
  void constraintsNarrowEveryMethod() throws Exception {
    c.registerAllServices(new Gripper("left"), "left");
    c.registerAllServices(new Gripper("right"), "right");
    TRADEServiceConstraints right = new TRADEServiceConstraints().inGroups("right");
    Checked p = c.proxy(Checked.class, right);
    right.inGroups("nowhere"); // the proxy took a copy
    assertEquals("right grips 1", p.grip(1));
    assertEquals("left grips 1", c.proxy(Checked.class,
        new TRADEServiceConstraints().inGroups("right").or(new TRADEServiceConstraints().inGroups("left"))
            .notInGroups("right")).grip(1));
  }

  @Test
  void aServiceThatLeftIsFoundAgainOnTheNextCall() throws Exception {
    Gripper first = new Gripper("first");
    c.registerAllServices(first, "arm");
    Checked p = c.proxy(Checked.class);
    assertEquals("first grips 1", p.grip(1));

    c.deregister(first);
    c.registerAllServices(new Gripper("second"), "arm");
    assertEquals("second grips 1", p.grip(1));
  }

  @Test
  void aRemoteProviderThatLeavesIsReplaced() throws Exception {
    TRADEContainer a = remote("A");
    TRADEContainer b = remote("B");
    try (a; b) {
      a.registerAllServices(new Gripper("A"), "arm");
      TRADEContainer caller = TRADEContainer.builder().name("caller")
          .property("CONNECTCONTAINERS", a.getServerAddresses().get(0) + "," + b.getServerAddresses().get(0))
          .build();
      try (caller) {
        Checked p = caller.proxy(Checked.class);
        Await.until(WAIT, () -> caller.getAvailableServices(named("grip")).size() == 2, "A's services");
        assertEquals("A grips 1", p.grip(1));

        b.registerAllServices(new Gripper("B"), "arm");
        Await.until(WAIT, () -> caller.getAvailableServices(named("grip")).size() == 4, "B's services");
        assertEquals("A grips 1", p.grip(1), "the proxy keeps the service it found");

        a.close();
        Await.until(WAIT, () -> caller.getAvailableServices(named("grip")).size() == 2, "A to leave");
        assertEquals("B grips 1", p.grip(1));
      }
    }
  }

  private static TRADEServiceConstraints named(String name) {
    return new TRADEServiceConstraints().name(name);
  }

  private static TRADEContainer remote(String name) {
    return Hubs.hubBuilder(name).build();
  }

  // Interfaces that cannot stand for services fail when the proxy is made, naming the method.

  public interface Generic {
    <T> String grip(T how);
  }

  public interface TypeVariableParameter<T> {
    String grip(T how);
  }

  public interface RawFuture {
    @SuppressWarnings("rawtypes")
    CompletableFuture grip(int force);
  }

  public interface PlainFuture {
    Future<String> grip(int force);
  }

  @Test
  void badInterfacesFailEagerlyNamingTheMethodAndTheFix() {
    assertEquals(Gripper.class.getName() + " is not an interface; a proxy implements an"
        + " interface: declare the services' methods in one and pass it",
        assertThrows(IllegalArgumentException.class, () -> c.proxy(Gripper.class)).getMessage());
    assertEquals("Method is generic; a service has concrete parameter types, so declare them (a"
        + " proxy finds the service by them)\n    for method " + Generic.class.getName() + ".grip",
        assertThrows(IllegalArgumentException.class, () -> c.proxy(Generic.class)).getMessage());
    assertTrue(assertThrows(IllegalArgumentException.class, () -> c.proxy(TypeVariableParameter.class))
        .getMessage().startsWith("Method parameter 0 has the type variable T; declare a concrete type"));
    assertTrue(assertThrows(IllegalArgumentException.class, () -> c.proxy(RawFuture.class))
        .getMessage().contains("declare it, e.g. CompletableFuture<Boolean>"));
    assertTrue(assertThrows(IllegalArgumentException.class, () -> c.proxy(PlainFuture.class))
        .getMessage().startsWith("Method returns Future; return CompletableFuture<T>"));
  }
}
