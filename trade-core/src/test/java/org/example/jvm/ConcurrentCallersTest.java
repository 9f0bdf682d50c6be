package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Many callers share one link between two containers on loopback: every reply reaches the call that
 * asked for it, once, and nothing is lost; a 16 MiB argument and result travel intact.
 */
class ConcurrentCallersTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private static final int THREADS = 64;
  private static final int CALLS = 500;

  /** Provided services; records every argument it saw. */
  public static final class Mixer {
    final Set<Long> seen = ConcurrentHashMap.newKeySet();
    final AtomicInteger calls = new AtomicInteger();

    @TRADEService
    public String mix(long x) {
      calls.incrementAndGet();
      seen.add(x);
      return x + ":" + Long.toHexString(scramble(x));
    }

    @TRADEService
    public byte[] invert(byte[] data) {
      byte[] r = new byte[data.length];
      for (int i = 0; i < data.length; i++) {
        r[i] = (byte) ~data[i];
      }
      return r;
    }

    @TRADEService
    public byte[] sha256(byte[] data) {
      return ConcurrentCallersTest.sha256(data);
    }
  }

  static long scramble(long x) {
    x *= 0x9E3779B97F4A7C15L;
    return x ^ (x >>> 29);
  }

  static byte[] sha256(byte[] data) {
    try {
      return MessageDigest.getInstance("SHA-256").digest(data);
    } catch (NoSuchAlgorithmException e) {
      throw new AssertionError(e);
    }
  }

  private final Mixer mixer = new Mixer();
  private TRADEContainer provider;
  private TRADEContainer caller;

  @BeforeEach
  void link() throws Exception {
    provider = Hubs.hubBuilder("provider").build();
    provider.registerAllServices(mixer, "mixer");
    // A lost reply fails its call after 20 s instead of hanging the test.
    caller = TRADEContainer.builder().name("caller").property("CALLTIMEOUT", "20000")
        .property("CONNECTCONTAINERS", provider.getServerAddresses().get(0)).build();
    Await.until(WAIT, () -> caller.getAvailableServices(new TRADEServiceConstraints().inGroups("mixer"))
        .size() == 3, "the provider's services");
  }

  @AfterEach
  void close() {
    caller.close();
    provider.close();
  }

  private TRADEServiceInfo service(String name) throws Exception {
    TRADEServiceInfo s = caller.getAvailableService(new TRADEServiceConstraints().name(name));
    assertTrue(!s.isLocal(), name + " must be remote");
    return s;
  }

  @Test
  void everyReplyReachesItsOwnCallExactlyOnce() throws Exception {
    TRADEServiceInfo mix = service("mix");
    Queue<String> problems = new ConcurrentLinkedQueue<>();
    CountDownLatch go = new CountDownLatch(1);
    CountDownLatch done = new CountDownLatch(THREADS);
    List<Thread> threads = new ArrayList<>();
    for (int t = 0; t < THREADS; t++) {
      long base = (long) t << 32;
      Thread thread = new Thread(() -> {
        try {
          go.await();
          for (int i = 0; i < CALLS; i++) {
            long x = base | i;
            String reply = mix.call(String.class, x);
            String expected = x + ":" + Long.toHexString(scramble(x));
            if (!expected.equals(reply)) {
              problems.add("call " + x + " got " + reply);
            }
          }
        } catch (Exception e) {
          problems.add(Thread.currentThread().getName() + ": " + e);
        } finally {
          done.countDown();
        }
      }, "caller-" + t);
      thread.setDaemon(true);
      threads.add(thread);
      thread.start();
    }
    long start = System.nanoTime();
    go.countDown();
    assertTrue(done.await(60, TimeUnit.SECONDS), "callers still running after 60 s");
    long ms = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - start);
    System.out.println(THREADS * CALLS + " calls from " + THREADS + " threads in " + ms + " ms");
    assertEquals(List.of(), List.copyOf(problems).subList(0, Math.min(10, problems.size())));
    assertEquals(THREADS * CALLS, mixer.calls.get(), "invocations (a duplicate would add one)");
    assertEquals(THREADS * CALLS, mixer.seen.size(), "distinct arguments seen by the provider");
  }

  @Test
  void sixteenMebibytesTravelBothWays() throws Exception {
    byte[] data = new byte[16 << 20];
    new Random(42).nextBytes(data);
    byte[] expectedInverted = new Mixer().invert(data);

    assertArrayEquals(sha256(data), service("sha256").call(byte[].class, (Object) data),
        "the argument as the provider received it");
    byte[] inverted = service("invert").call(byte[].class, (Object) data);
    assertEquals(data.length, inverted.length);
    assertArrayEquals(sha256(expectedInverted), sha256(inverted), "the result as it came back");
  }
}
