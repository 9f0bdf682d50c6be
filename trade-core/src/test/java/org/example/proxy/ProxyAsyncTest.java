package org.example.proxy;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInvocationException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.UncheckedTRADEException;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/** A proxy's asynchronous methods against a provider in another container. */
class ProxyAsyncTest {
  private static final Duration WAIT = Duration.ofSeconds(30);
  /** More than any thread pool of a bounded size would run at once (the old proxy pool ran 16). */
  private static final int OUTSTANDING = 64;

  @RegisterExtension final Hubs net = new Hubs();

  /** Answers once released; counts the calls that arrived. */
  public static class Slow {
    final AtomicInteger arrived = new AtomicInteger();
    final CountDownLatch release = new CountDownLatch(1);

    @TRADEService
    public String slow(int i) throws InterruptedException {
      arrived.incrementAndGet();
      // Bounded, so that a failing test cannot keep the provider's threads for ever.
      release.await(60, TimeUnit.SECONDS);
      return "done " + i;
    }

    @TRADEService
    public void jam() throws ProxyTest.JammedException {
      throw new ProxyTest.JammedException("jammed");
    }
  }

  public interface SlowAsync {
    CompletableFuture<String> slow(int i);
  }

  public interface Declared {
    CompletableFuture<Void> jam() throws ProxyTest.JammedException;
  }

  public interface Checked {
    CompletionStage<Void> jam() throws TRADEException;
  }

  public interface Unchecked {
    CompletableFuture<Void> jam();
  }

  @Test
  void outstandingCallsHoldNoThread() throws Exception {
    TRADEContainer provider = net.hub("provider");
    Slow slow = new Slow();
    provider.registerAllServices(slow, "slow");
    TRADEContainer caller = net.spoke("caller", provider);
    Await.until(WAIT, () -> !caller.getAvailableServices(
        new TRADEServiceConstraints().name("slow")).isEmpty(), "the provider's service");
    SlowAsync p = caller.proxy(SlowAsync.class);

    List<CompletableFuture<String>> calls = new ArrayList<>();
    try {
      for (int i = 0; i < OUTSTANDING; i++) {
        calls.add(p.slow(i));
      }
      // Every call reached the provider at once: none waits for a thread of the caller's.
      Await.until(WAIT, () -> slow.arrived.get() == OUTSTANDING,
          "all " + OUTSTANDING + " calls to arrive");
      List<String> waiting = threadsIn("dev.trade.internal.proxy.");
      assertTrue(waiting.isEmpty(), "threads in the proxy while replies are outstanding: " + waiting);
    } finally {
      slow.release.countDown();
    }
    for (int i = 0; i < OUTSTANDING; i++) {
      assertEquals("done " + i, calls.get(i).get(WAIT.toSeconds(), TimeUnit.SECONDS));
    }
  }

  @Test
  void remoteFailuresAreTheTypesASynchronousCallWouldThrow() throws Exception {
    TRADEContainer provider = net.hub("provider");
    provider.registerAllServices(new Slow(), "slow");
    TRADEContainer caller = net.spoke("caller", provider);
    Await.until(WAIT, () -> !caller.getAvailableServices(
        new TRADEServiceConstraints().name("jam")).isEmpty(), "the provider's service");

    Throwable declared = failure(caller.proxy(Declared.class).jam());
    assertInstanceOf(ProxyTest.JammedException.class, declared);
    assertEquals("jammed", declared.getMessage());

    Throwable checked = failure(caller.proxy(Checked.class).jam().toCompletableFuture());
    assertInstanceOf(TRADEInvocationException.class, checked);
    assertInstanceOf(ProxyTest.JammedException.class, checked.getCause());

    Throwable unchecked = failure(caller.proxy(Unchecked.class).jam());
    assertInstanceOf(UncheckedTRADEException.class, unchecked);
    assertInstanceOf(TRADEInvocationException.class, unchecked.getCause());
    assertInstanceOf(ProxyTest.JammedException.class, unchecked.getCause().getCause());
  }

  @Test
  void callsAfterTheContainerClosedFailAtOnce() throws Exception {
    TRADEContainer c = net.hub("closing");
    c.registerAllServices(new Slow(), "slow");
    Unchecked p = c.proxy(Unchecked.class);
    c.close();
    Throwable closed = failure(p.jam());
    assertInstanceOf(IllegalStateException.class, closed);
    assertEquals("container closing is closed", closed.getMessage());
  }

  private static Throwable failure(CompletableFuture<?> f) throws Exception {
    return assertThrows(ExecutionException.class, () -> f.get(WAIT.toSeconds(), TimeUnit.SECONDS))
        .getCause();
  }

  /** The threads with a frame of a class whose name starts with {@code prefix}. */
  private static List<String> threadsIn(String prefix) {
    List<String> found = new ArrayList<>();
    for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
      for (StackTraceElement frame : e.getValue()) {
        if (frame.getClassName().startsWith(prefix)) {
          found.add(e.getKey().getName());
          break;
        }
      }
    }
    return found;
  }
}
