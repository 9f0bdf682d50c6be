package org.example.net;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A lone caller reads its replies from the link itself, and hands reading back when others call
 * too; callers that come and go while the other container calls back over the same link all get
 * their own answers, and none waits for its deadline.
 */
@Timeout(120)
class LoneAndManyCallersTest {
  private static final Duration WAIT = Duration.ofSeconds(10);

  /** Answers with its container's name, so that a reply that reached the wrong call shows. */
  public static final class Echo {
    private final String name;

    Echo(String name) {
      this.name = name;
    }

    @TRADEService
    public String echo(long x) {
      return name + ":" + x;
    }
  }

  private final TRADEContainer a = Hubs.hubBuilder("a").property("CALLTIMEOUT", "5000").build();
  private final TRADEContainer b = TRADEContainer.builder().name("b").property("CALLTIMEOUT", "5000")
      .property("CONNECTCONTAINERS", a.getServerAddresses().get(0)).build();
  private final ExecutorService threads = Executors.newCachedThreadPool();
  private final Queue<String> problems = new ConcurrentLinkedQueue<>();

  @AfterEach
  void close() {
    threads.shutdownNow();
    b.close();
    a.close();
  }

  private static TRADEServiceInfo remoteEcho(TRADEContainer c, String of) throws TRADEException {
    TRADEServiceConstraints constraints = new TRADEServiceConstraints().name("echo").inGroups(of);
    Await.until(WAIT, () -> !c.getAvailableServices(constraints).isEmpty(), of + "'s echo");
    return c.getAvailableService(constraints);
  }

  /** Calls {@code echo} {@code calls} times from one thread, checking every answer. */
  private Future<?> calling(TRADEServiceInfo echo, String of, long first, int calls) {
    return threads.submit(() -> {
      for (long x = first; x < first + calls; x++) {
        try {
          String answer = echo.call(String.class, x);
          if (!(of + ":" + x).equals(answer)) {
            problems.add("call " + x + " to " + of + " got " + answer);
          }
        } catch (TRADEException e) {
          problems.add("call " + x + " to " + of + ": " + e);
        }
      }
    });
  }

  @Test
  void callersThatComeAndGoBesideALoneOneAndCallsBackAllGetTheirOwnAnswers() throws Exception {
    a.registerAllServices(new Echo("a"), "a");
    b.registerAllServices(new Echo("b"), "b");
    TRADEServiceInfo toB = remoteEcho(a, "b");
    TRADEServiceInfo toA = remoteEcho(b, "a");

    Future<?> lone = calling(toB, "b", 0, 4_000);
    Future<?> back = calling(toA, "a", 0, 2_000); // calls over the same link, the other way
    for (int burst = 0; burst < 10; burst++) {
      List<Future<?>> others = new ArrayList<>();
      for (int t = 0; t < 3; t++) {
        others.add(calling(toB, "b", 1_000_000L * (1 + burst * 3 + t), 100));
      }
      for (Future<?> f : others) {
        f.get(60, TimeUnit.SECONDS);
      }
    }
    lone.get(60, TimeUnit.SECONDS);
    back.get(60, TimeUnit.SECONDS);
    assertTrue(problems.isEmpty(), problems.size() + " problems, first: " + problems.peek());
  }
}
