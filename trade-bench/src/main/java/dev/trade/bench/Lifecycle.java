package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;

/**
 * How fast a peer notices a container that starts and one that dies. The peer is a container in
 * this JVM; each iteration starts a provider in a fresh JVM ({@link ProviderMain}). Both use
 * multicast discovery in range {@code localhost} (loopback, TTL 0) on a random port and a system id
 * of their own, so no other TRADE system on the host can interfere.
 *
 * <ul>
 *   <li>start → callable: from just before the provider's {@code build()} (its clock) to the end of
 *       the peer's first successful call of its service, made from the peer's {@code joined}
 *       callback; also from the moment this JVM spawned the provider's JVM (JVM start included).
 *   <li>kill → left: from just before {@code kill -9} of the provider's JVM to the peer's
 *       {@code left} callback.
 * </ul>
 */
final class Lifecycle {
  private final Path logs;
  private final int iterations;

  Lifecycle(Path logs, boolean quick) {
    this.logs = logs;
    this.iterations = quick ? 2 : 8;
  }

  /** Multicast discovery and announcing on loopback, isolated by system id and port. */
  static TRADEContainer.Builder discovering(TRADEContainer.Builder b, String sysId, String port) {
    return b.property("STARTDISCOVERY", "true")
        .property("STARTBROADCAST", "true")
        .property("DISCOVERYRANGE", "localhost")
        .property("BROADCASTPORT", port)
        .property("TRADESYSID", sysId);
  }

  /** The peer's callbacks. */
  public static final class Listener {
    volatile CompletableFuture<long[]> joined = new CompletableFuture<>();
    volatile CompletableFuture<Long> left = new CompletableFuture<>();

    @TRADEService
    public void onJoined(TRADEServiceInfo info) {
      long heard = Clock.epochMicros();
      try {
        boolean ok = info.call(boolean.class, 2);
        joined.complete(new long[] {heard, Clock.epochMicros(), ok ? 1 : 0});
      } catch (Exception e) {
        joined.completeExceptionally(e);
      }
    }

    @TRADEService
    public void onLeft(TRADEServiceInfo info) {
      left.complete(Clock.epochMicros());
    }
  }

  void run(Json json) throws Exception {
    String sysId = "bench-" + Long.toHexString(ThreadLocalRandom.current().nextLong());
    String port = Integer.toString(40_000 + ThreadLocalRandom.current().nextInt(20_000));
    Path archive = logs.resolve("provider-appcds.jsa");
    try (TRADEContainer peer = discovering(TRADEContainer.builder().name("peer"), sysId, port).build()) {
      Listener listener = new Listener();
      json.key("iterations").beginArray();
      for (int i = 0; i < iterations; i++) {
        iteration(peer, listener, sysId, port, "run" + i, List.of("-Xmx64m"), true, json);
      }
      json.endArray();
      // The same with an application class-data archive (AppCDS, JDK 13+): a training run writes
      // it at exit, later JVMs map TRADE's and the JDK's classes instead of loading them.
      iteration(peer, listener, sysId, port, "train", List.of("-Xmx64m",
          "-XX:ArchiveClassesAtExit=" + archive), false, null);
      json.key("iterations_appcds").beginArray();
      for (int i = 0; i < iterations; i++) {
        iteration(peer, listener, sysId, port, "cds" + i, List.of("-Xmx64m",
            "-XX:SharedArchiveFile=" + archive), true, json);
      }
      json.endArray();
    }
  }

  private void iteration(TRADEContainer peer, Listener listener, String sysId, String port,
      String group, List<String> options, boolean kill, Json json) throws Exception {
    listener.joined = new CompletableFuture<>();
    listener.left = new CompletableFuture<>();
    TRADEServiceConstraints mine = new TRADEServiceConstraints().name("lifecyclePing").inGroups(group);
    peer.requestNotification(listener, "joined", mine, null, "onJoined");
    peer.requestNotification(listener, "left", mine, null, "onLeft");
    Jvm provider = Jvm.start(Jvm.tradeClassPath(), options, ProviderMain.class,
        logs.resolve("provider.log"), sysId, port, group);
    try {
      String[] built = provider.await("BUILT", 30_000).split(" ");
      long before = Long.parseLong(built[0]);
      long[] j = listener.joined.get(30, TimeUnit.SECONDS);
      if (j[2] != 1) {
        throw new IllegalStateException("wrong answer from the provider");
      }
      if (!kill) {
        return;
      }
      Thread.sleep(500); // steady state: heartbeats flowing
      long killed = Clock.epochMicros();
      provider.kill();
      long left = listener.left.get(30, TimeUnit.SECONDS);
      json.begin();
      json.field("start_to_callable_ms", (j[1] - before) / 1e3);
      json.field("spawn_to_callable_ms", (j[1] - provider.spawnedEpochMicros) / 1e3);
      json.field("start_to_joined_ms", (j[0] - before) / 1e3);
      json.field("build_ms", (Long.parseLong(built[1]) - before) / 1e3);
      json.field("kill_to_left_ms", (left - killed) / 1e3);
      json.end();
      System.err.printf("lifecycle %s: start->callable %.1f ms (from JVM spawn %.1f ms), "
          + "kill->left %.1f ms%n", group, (j[1] - before) / 1e3,
          (j[1] - provider.spawnedEpochMicros) / 1e3, (left - killed) / 1e3);
    } finally {
      provider.close();
      peer.cancelNotification(listener, "joined", null);
      peer.cancelNotification(listener, "left", null);
    }
  }
}
