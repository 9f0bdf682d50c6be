package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Notifications and non-blocking calls (docs/notifications.md), three measurements:
 *
 * <ul>
 *   <li><b>every lateness</b> at 1, 10 and 100 ms periods: a bare {@link ScheduledThreadPoolExecutor}
 *       at a fixed rate, TRADE's {@code every} with a local callback, and {@code every} with a
 *       service in another JVM whose result reaches a callback here (remote). Each delivery's time
 *       minus its place on the period grid, the grid anchored at the least late delivery (so a
 *       constant cost, the remote call's, does not count; jitter does);
 *   <li><b>streaming</b>: {@code every} 1 ms with a service in another JVM returning a small value
 *       and a 64 KB one, delivered to a callback here: deliveries per second and skipped ones;
 *   <li><b>callAsync</b>: 10,000 calls from one thread to a container in another JVM that is
 *       stopped (SIGSTOP) so that all stay outstanding; heap and threads per outstanding call, then
 *       the time until all complete once it runs again.
 * </ul>
 */
final class NotifyBench {
  private static final long[] PERIODS_MS = {1, 10, 100};
  private static final int OUTSTANDING = 10_000;

  private final Path logs;
  private final boolean quick;

  NotifyBench(Path logs, boolean quick) {
    this.logs = logs;
    this.quick = quick;
  }

  /** Records when it is called back. */
  public static final class Ticks {
    final long[] at;
    final AtomicInteger n = new AtomicInteger();
    final CountDownLatch full = new CountDownLatch(1);
    final AtomicLong bytes = new AtomicLong();

    Ticks(int count) {
      at = new long[count];
    }

    void record() {
      long now = System.nanoTime();
      int i = n.getAndIncrement();
      if (i < at.length) {
        at[i] = now;
        if (i == at.length - 1) {
          full.countDown();
        }
      }
    }

    @TRADEService
    public void tick() {
      record();
    }

    @TRADEService
    public void value(Object v) {
      bytes.addAndGet(v instanceof byte[] ? ((byte[]) v).length : 4);
      record();
    }
  }

  void run(Json json) throws Exception {
    try (Jvm far = Jvm.start(Jvm.tradeClassPath(), List.of("-Xmx256m"), NotifyProviderMain.class,
        logs.resolve("notify-provider.log"));
        TRADEContainer here = TRADEContainer.builder().name("notify-bench")
            .property("CONNECTCONTAINERS", far.await("READY ", 30_000))
            .property("FAILURETIMEOUT", "120000").property("CALLTIMEOUT", "120000").build()) {
      TRADEServiceInfo small = here.waitForService(named("small"), Duration.ofSeconds(30));
      TRADEServiceInfo big = here.waitForService(named("big"), Duration.ofSeconds(30));
      TRADEServiceInfo echo = here.waitForService(named("echo"), Duration.ofSeconds(30));
      json.key("every_lateness").begin();
      for (long period : PERIODS_MS) {
        lateness(json, here, small, period);
      }
      json.end();
      json.key("streaming").begin();
      stream(json, here, "small", small);
      stream(json, here, "64KB", big);
      json.end();
      outstanding(json, far, echo);
    }
  }

  /**
   * The bare executor, {@code every} with a local callback and with a remote service, in rounds
   * that interleave them (the order reversed every other round), so that a load that changes
   * during the run weighs on all three alike: pooled percentiles, and each round's p99 with the
   * load average before it.
   */
  private void lateness(Json json, TRADEContainer here, TRADEServiceInfo remote, long period)
      throws Exception {
    int rounds = quick ? 3 : 5;
    int count = (int) Math.max(10, (quick ? 500 : 3000) / period * (period == 100 ? 2 : 1) / rounds);
    String[] kinds = {"bare_executor", "trade_local", "trade_remote"};
    Stats[] pooled = {new Stats(count * rounds), new Stats(count * rounds), new Stats(count * rounds)};
    double[][] p99 = new double[3][rounds];
    double[] load = new double[rounds];
    for (int r = 0; r < rounds; r++) {
      load[r] = ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
      for (int i = 0; i < 3; i++) {
        int k = r % 2 == 0 ? i : 2 - i;
        Stats s = k == 0 ? bare(period, count) : every(here, period, count, k == 1 ? null : remote);
        pooled[k].addAll(s);
        p99[k][r] = Stats.round(s.percentileMicros(99));
      }
    }
    json.key(period + "ms").begin();
    json.field("rounds", rounds);
    json.key("load_average_before_rounds").beginArray();
    for (double l : load) {
      json.value(Stats.round(l));
    }
    json.endArray();
    for (int k = 0; k < 3; k++) {
      json.key(kinds[k]);
      pooled[k].writeTo(json);
    }
    json.key("p99_us_by_round").begin();
    for (int k = 0; k < 3; k++) {
      json.key(kinds[k]).beginArray();
      for (double v : p99[k]) {
        json.value(v);
      }
      json.endArray();
    }
    json.end();
    json.end();
  }

  private static TRADEServiceConstraints named(String name) {
    return new TRADEServiceConstraints().name(name).inGroups("notifybench");
  }

  private static Stats bare(long periodMs, int count) throws InterruptedException {
    Ticks t = new Ticks(count);
    ScheduledThreadPoolExecutor executor = new ScheduledThreadPoolExecutor(1);
    try {
      executor.scheduleAtFixedRate(t::record, periodMs, periodMs, TimeUnit.MILLISECONDS);
      t.full.await();
    } finally {
      executor.shutdownNow();
    }
    return lateness(t.at, periodMs);
  }

  private static Stats every(TRADEContainer here, long periodMs, int count, TRADEServiceInfo service)
      throws Exception {
    Ticks t = new Ticks(count);
    List<TRADEServiceInfo> infos = new ArrayList<>(here.registerAllServices(t));
    TRADEServiceInfo callback = infos.stream()
        .filter(s -> s.serviceName.equals(service == null ? "tick" : "value")).findFirst().get();
    String id = here.requestNotification("every", periodMs,
        service == null ? List.of() : List.of(service), callback);
    try {
      t.full.await();
    } finally {
      here.cancelNotification(id);
      here.deregister(t);
    }
    return lateness(t.at, periodMs);
  }

  /**
   * Each time minus its place on the grid of {@code periodMs}: the i-th time takes the slot it
   * falls in, counted from the first, and never one before the previous time's (so a skipped
   * delivery does not make every later one look a period late); the grid is anchored at the least
   * late time.
   */
  static Stats lateness(long[] at, long periodMs) {
    long period = TimeUnit.MILLISECONDS.toNanos(periodMs);
    long[] offsets = new long[at.length];
    long slot = 0;
    long anchor = Long.MAX_VALUE;
    for (int i = 0; i < at.length; i++) {
      slot = i == 0 ? 0 : Math.max(slot + 1, (at[i] - at[0]) / period);
      offsets[i] = at[i] - slot * period;
      anchor = Math.min(anchor, offsets[i]);
    }
    Stats s = new Stats(at.length);
    for (long o : offsets) {
      s.add(o - anchor);
    }
    return s;
  }

  private void stream(Json json, TRADEContainer here, String label, TRADEServiceInfo service)
      throws Exception {
    Ticks t = new Ticks(0); // counts only
    List<TRADEServiceInfo> infos = new ArrayList<>(here.registerAllServices(t));
    TRADEServiceInfo callback = infos.stream().filter(s -> s.serviceName.equals("value"))
        .findFirst().get();
    long seconds = quick ? 2 : 5;
    String id = here.requestNotification("every", 1L, List.of(service), callback);
    long start = System.nanoTime();
    TimeUnit.SECONDS.sleep(seconds); // a measuring window, not a wait for a condition
    long skipped = skipped(here, id);
    int delivered = t.n.get();
    long elapsed = System.nanoTime() - start;
    here.cancelNotification(id);
    here.deregister(t);
    double perSecond = delivered / (elapsed / 1e9);
    json.key(label).begin();
    json.field("period_ms", 1);
    json.field("deliveries_per_s", Stats.round(perSecond));
    json.field("mb_per_s", Stats.round(t.bytes.get() / (elapsed / 1e9) / 1e6));
    json.field("skipped", skipped);
    json.end();
  }

  @SuppressWarnings("unchecked")
  private static long skipped(TRADEContainer here, String id) throws Exception {
    String container = id.substring(0, id.lastIndexOf(':'));
    for (TRADEServiceInfo s : here.getAvailableServices(
        new TRADEServiceConstraints().inGroups("trade.system").name("listNotifications"))) {
      if (s.getContainerId().equals(container)) {
        for (Map<String, Object> n : (List<Map<String, Object>>) s.call(List.class)) {
          if (n.get("id").equals(id)) {
            return (Long) n.get("skipped");
          }
        }
      }
    }
    return -1;
  }

  private static void outstanding(Json json, Jvm far, TRADEServiceInfo echo) throws Exception {
    echo.callAsync(int.class, 0).get(30, TimeUnit.SECONDS); // warm
    signal("STOP", far.pid());
    try {
      long heapBefore = usedHeap();
      int threadsBefore = ManagementFactory.getThreadMXBean().getThreadCount();
      long start = System.nanoTime();
      List<CompletableFuture<Integer>> calls = new ArrayList<>(OUTSTANDING);
      for (int i = 0; i < OUTSTANDING; i++) {
        calls.add(echo.callAsync(Integer.class, i));
      }
      long issued = System.nanoTime() - start;
      int done = (int) calls.stream().filter(CompletableFuture::isDone).count();
      long heapAfter = usedHeap();
      int threadsAfter = ManagementFactory.getThreadMXBean().getThreadCount();
      signal("CONT", far.pid());
      long resumed = System.nanoTime();
      for (int i = 0; i < OUTSTANDING; i++) {
        if (calls.get(i).get(60, TimeUnit.SECONDS) != i) {
          throw new IllegalStateException("wrong reply to call " + i);
        }
      }
      long completed = System.nanoTime() - resumed;
      json.key("call_async").begin();
      json.field("calls", OUTSTANDING);
      json.field("done_before_resume", done);
      json.field("issue_ms", Stats.round(issued / 1e6));
      json.field("heap_bytes_per_outstanding_call",
          Math.round((double) (heapAfter - heapBefore) / (OUTSTANDING - done)));
      json.field("threads_added", threadsAfter - threadsBefore);
      json.field("complete_after_resume_ms", Stats.round(completed / 1e6));
      json.end();
    } finally {
      signal("CONT", far.pid());
    }
  }

  private static long usedHeap() {
    for (int i = 0; i < 3; i++) {
      System.gc();
    }
    return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
  }

  private static void signal(String signal, long pid) throws Exception {
    Process p = new ProcessBuilder("kill", "-" + signal, Long.toString(pid)).inheritIO().start();
    if (!p.waitFor(10, TimeUnit.SECONDS) || p.exitValue() != 0) {
      throw new IllegalStateException("kill -" + signal + " " + pid + " failed");
    }
  }
}
