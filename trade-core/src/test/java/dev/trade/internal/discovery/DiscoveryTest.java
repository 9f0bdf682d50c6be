package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.address;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.discovery.BadPacketException.Reason;
import dev.trade.testing.Await;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Several discovery instances in one JVM, on the loopback interface with TTL 0 (range
 * LOCALHOST): nothing leaves the machine. Run inside a private network namespace anyway
 * ({@code unshare -n}, then {@code ip link set lo up}), as CI does. Every wait has a deadline.
 */
class DiscoveryTest {
  private static final Duration FAST = Duration.ofMillis(50);
  private static final Duration NEVER = Duration.ofMinutes(10);

  private final List<Discovery> started = new ArrayList<>();
  private InetAddress group;
  private int port;

  @BeforeEach
  void pickGroupAndPort() throws IOException {
    LoopbackMulticast.assumeUsable();
    group = LoopbackMulticast.randomGroup();
    port = LoopbackMulticast.freePort();
  }

  @AfterEach
  void closeAll() {
    started.forEach(Discovery::close);
  }

  @Test
  void threeContainersHearEachOtherAndNotThemselves() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    Recorder rc = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
    start("alpha", "s3cret", "c", 7003, rc, b -> b.interval(FAST));
    ra.awaitHeard("b", 1);
    ra.awaitHeard("c", 1);
    rb.awaitHeard("a", 1);
    rb.awaitHeard("c", 1);
    rc.awaitHeard("a", 1);
    rc.awaitHeard("b", 1);
    ra.awaitDrops(Reason.OWN, 1);
    assertEquals(0, ra.heardFrom("a"));
    Announcement fromB = ra.heard().stream().filter(x -> x.containerId().equals("b")).findFirst()
        .orElseThrow();
    assertEquals(List.of(address("127.0.0.1", 7002)), fromB.addresses());
    assertEquals("name-b", fromB.containerName());
    assertTrue(ra.sources().stream().allMatch(InetAddress::isLoopbackAddress));
    assertTrue(a.dropCounts().get(Reason.OWN) >= 1);
    assertEquals(List.of(LoopbackMulticast.loopback().getName()), a.interfaceNames());
  }

  @Test
  void aNewcomerAndTheOthersHearEachOtherAtOnceNotAtTheNextInterval() throws IOException {
    Recorder ra = new Recorder();
    start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(NEVER));
    ra.awaitDrops(Reason.OWN, Announcer.BURST_MILLIS.length); // a's start burst is over
    Recorder rb = new Recorder();
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(NEVER));
    ra.awaitHeard("b", 1);
    // Only possible because a answers a newcomer: its next interval is ten minutes away.
    rb.awaitHeard("a", 1);
  }

  @Test
  void answersToANewcomerReachItAloneNotTheGroup() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(NEVER));
    Discovery b = start("alpha", "s3cret", "b", 7002, rb, x -> x.interval(NEVER));
    ra.awaitHeard("b", Announcer.BURST_MILLIS.length); // b's start burst is over
    rb.awaitHeard("a", 1);
    Recorder rc = new Recorder();
    start("alpha", "s3cret", "c", 7003, rc, x -> x.interval(NEVER));
    // Answers: the next intervals of a and b are ten minutes away.
    rc.awaitHeard("a", 1);
    rc.awaitHeard("b", 1);
    // b's burst was over before c started: the first packet of b that c heard is b's answer.
    List<Announcement> heardByC = rc.heard();
    int first = heardByC.indexOf(heardByC.stream().filter(x -> x.containerId().equals("b"))
        .findFirst().orElseThrow());
    long answer = heardByC.get(first).sequence();
    assertTrue(rc.answers().get(first), "c's listener is told that b's packet is an answer");
    // Then a marker from b to the group: a's socket receives in order, so an answer b had sent to
    // the group would have reached a before it.
    b.announceNow();
    ra.await("b's marker", () -> ra.heard().stream()
        .anyMatch(x -> x.containerId().equals("b") && x.sequence() > answer));
    assertTrue(ra.heard().stream().noneMatch(x -> x.containerId().equals("b")
        && x.sequence() == answer), "a heard b's answer to c: " + ra.heard());
    List<Announcement> heardByA = ra.heard();
    for (int i = 0; i < heardByA.size(); i++) {
      if (heardByA.get(i).containerId().equals("b") && heardByA.get(i).sequence() > answer) {
        assertFalse(ra.answers().get(i), "b's marker went to the group");
      }
    }
  }

  @Test
  void anotherSystemOnTheSameGroupAndPortIsCountedButNeverHeard() throws IOException {
    Recorder ra = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    start("beta", "s3cret", "x", 7002, new Recorder(), b -> b.interval(FAST));
    ra.awaitDrops(Reason.FOREIGN_SYSTEM, 3);
    assertEquals(List.of(), ra.heard());
    assertTrue(a.dropCounts().get(Reason.FOREIGN_SYSTEM) >= 3);
  }

  @Test
  void twoSystemsCoexistOnOneGroupAndPort() throws IOException {
    Recorder a1 = new Recorder();
    Recorder a2 = new Recorder();
    Recorder b1 = new Recorder();
    Recorder b2 = new Recorder();
    start("alpha", "s3cret", "a1", 7001, a1, b -> b.interval(FAST));
    start("alpha", "s3cret", "a2", 7002, a2, b -> b.interval(FAST));
    start("beta", "other", "b1", 7003, b1, b -> b.interval(FAST));
    start("beta", "other", "b2", 7004, b2, b -> b.interval(FAST));
    a1.awaitHeard("a2", 2);
    a2.awaitHeard("a1", 2);
    b1.awaitHeard("b2", 2);
    b2.awaitHeard("b1", 2);
    for (Recorder r : List.of(a1, a2, b1, b2)) {
      r.awaitDrops(Reason.FOREIGN_SYSTEM, 2);
    }
    assertEquals(0, a1.count(x -> !x.systemId().equals("alpha")));
    assertEquals(0, b1.count(x -> !x.systemId().equals("beta")));
  }

  @Test
  void wrongCredentialsNeverJoin() throws IOException {
    Recorder ra = new Recorder();
    Recorder rz = new Recorder();
    start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    start("alpha", "guess", "z", 7002, rz, b -> b.interval(FAST));
    ra.awaitDrops(Reason.BAD_HMAC, 3);
    rz.awaitDrops(Reason.BAD_HMAC, 3);
    assertEquals(List.of(), ra.heard());
    assertEquals(List.of(), rz.heard());
  }

  @Test
  void setDiscoveryFalseStopsDeliveryAndTrueResumesIt() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
    ra.awaitHeard("b", 1);
    a.setDiscovery(false);
    assertFalse(a.isDiscovering());
    // Once one datagram was ignored, the receive thread has seen the switch: nothing after it
    // is delivered or counted.
    ra.await("a datagram ignored", () -> ra.ignoredCount() >= 1);
    int heard = ra.heardFrom("b");
    long own = a.dropCounts().get(Reason.OWN);
    ra.await("5 more datagrams ignored", () -> ra.ignoredCount() >= 6);
    assertEquals(heard, ra.heardFrom("b"));
    assertEquals(own, a.dropCounts().get(Reason.OWN));
    assertTrue(a.ignoredCount() >= 6);
    a.setDiscovery(true);
    ra.awaitHeard("b", heard + 1);
  }

  @Test
  void setBroadcastFalseStopsSendingAndTrueResumesIt() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
    rb.awaitHeard("a", 1);
    a.setBroadcast(false);
    assertFalse(a.isBroadcasting());
    long sent = a.sentCount();
    a.announceNow();
    // While a hears b five more times (250 ms at b's interval), a's own 50 ms ticks come and go.
    int fromB = ra.heardFrom("b");
    ra.awaitHeard("b", fromB + 5);
    assertEquals(sent, a.sentCount());
    long lastSeq = rb.heard().stream().filter(x -> x.containerId().equals("a"))
        .mapToLong(Announcement::sequence).max().orElseThrow();
    a.setBroadcast(true);
    rb.await("a heard again", () -> rb.count(x -> x.containerId().equals("a")
        && x.sequence() > lastSeq) > 0);
  }

  @Test
  void aContainerWithoutAddressesListensButAnnouncesNothing() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 0, ra, b -> b.interval(FAST));
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
    ra.awaitHeard("b", 5);
    assertEquals(0, a.sentCount());
    assertEquals(0, rb.heardFrom("a"));
  }

  @Test
  void announceNowSendsTheChangedAddresses() throws IOException {
    AtomicReference<List<InetSocketAddress>> listen =
        new AtomicReference<>(List.of(address("127.0.0.1", 7001)));
    Recorder rb = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 0, new Recorder(),
        b -> b.interval(NEVER).addresses(listen::get));
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(NEVER));
    rb.awaitHeardAt("a", address("127.0.0.1", 7001));
    // A wildcard listener is announced as the interface's own address.
    listen.set(List.of(address("0.0.0.0", 7009)));
    a.announceNow();
    rb.awaitHeardAt("a", address("127.0.0.1", 7009));
  }

  @Test
  void garbageOnThePortIsDroppedAndCountedAndDiscoveryGoesOn() throws IOException {
    Recorder ra = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.broadcast(false));
    InetSocketAddress target = new InetSocketAddress(group, port);
    int sent = 0;
    try (DatagramChannel ch = LoopbackMulticast.sender()) {
      Random random = new Random(99L);
      for (int i = 1; i <= 200; i++) {
        byte[] junk = new byte[random.nextInt(1400)];
        random.nextBytes(junk);
        ch.send(ByteBuffer.wrap(junk), target);
        sent++;
        if (i % 20 == 0) {
          // Lets the receiver catch up: the kernel drops what overflows the socket's buffer.
          int batch = sent;
          ra.await(batch + " drops", () -> ra.dropsOtherThanOwn() >= batch);
        }
      }
      byte[] valid = Fixtures.announcement("t", 1).encode(Fixtures.KEY);
      byte[] newer = valid.clone();
      newer[4] = 2;
      byte[] foreign = new Announcement(1, "beta", "t", "n", List.of(), 1, 1)
          .encode(Packets.deriveKey("beta", "s3cret"));
      byte[] forged = Fixtures.announcement("t", 1).encode(Packets.deriveKey("alpha", "guess"));
      for (byte[] p : List.of(new byte[1500], newer, foreign, forged)) {
        ch.send(ByteBuffer.wrap(p), target);
        sent++;
      }
      int expected = sent;
      ra.await(expected + " drops", () -> ra.dropsOtherThanOwn() >= expected);
      assertEquals(List.of(), ra.heard());
      assertTrue(ra.drops(Reason.TOO_LONG) >= 1);
      assertEquals(1, ra.drops(Reason.UNSUPPORTED_VERSION));
      assertEquals(1, ra.drops(Reason.FOREIGN_SYSTEM));
      assertEquals(1, ra.drops(Reason.BAD_HMAC));
      long counted = a.dropCounts().values().stream().mapToLong(Long::longValue).sum();
      assertEquals(expected, counted);
      // Still listening: a valid announcement is heard; sent again, just after, it counts as
      // overtaken (delivered twice), and an older one after a newer one as a replay.
      byte[] old = Fixtures.announcement("r", 1, System.currentTimeMillis() - 5000)
          .encode(Fixtures.KEY);
      byte[] current = Fixtures.announcement("r", 2).encode(Fixtures.KEY);
      ch.send(ByteBuffer.wrap(valid), target);
      ra.awaitHeard("t", 1);
      ch.send(ByteBuffer.wrap(valid), target);
      ra.awaitDrops(Reason.OVERTAKEN, 1);
      ch.send(ByteBuffer.wrap(current), target);
      ra.awaitHeard("r", 1);
      ch.send(ByteBuffer.wrap(old), target);
      ra.awaitDrops(Reason.REPLAYED, 1);
    }
  }

  @Test
  void closeStopsSendingAndListeningAndIsIdempotent() throws IOException {
    Recorder ra = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    ra.awaitDrops(Reason.OWN, 1);
    a.close();
    a.close();
    long sent = a.sentCount();
    a.announceNow();
    a.setBroadcast(false);
    a.setBroadcast(true);
    assertEquals(sent, a.sentCount());
    Await.until(Duration.ofSeconds(5), () -> receiveThreads() == 0,
        "the receiving thread to end with the last discovery on its group");
    // The port is free for the next container.
    Recorder rb = new Recorder();
    start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
    rb.awaitDrops(Reason.OWN, 1);
  }

  @Test
  void discoveriesOfOneJvmOnOneGroupShareOneReceivingThread() throws IOException {
    Recorder ra = new Recorder();
    Recorder rb = new Recorder();
    Recorder rc = new Recorder();
    Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST));
    Discovery b = start("alpha", "s3cret", "b", 7002, rb, x -> x.interval(FAST));
    // Another system on the same group and port: the packets are checked once per system.
    Discovery c = start("beta", "other", "c", 7003, rc, x -> x.interval(FAST));
    assertEquals(1, receiveThreads());
    ra.awaitHeard("b", 2);
    rb.awaitHeard("a", 2);
    rc.awaitDrops(Reason.OWN, 1);
    rc.awaitDrops(Reason.FOREIGN_SYSTEM, 1);
    assertEquals(0, rc.heard().size());
    ra.awaitDrops(Reason.FOREIGN_SYSTEM, 1);
    b.close();
    c.close();
    assertEquals(1, receiveThreads(), "a still listens");
    Recorder rd = new Recorder();
    start("alpha", "s3cret", "d", 7004, rd, x -> x.interval(FAST));
    ra.awaitHeard("d", 1);
    rd.awaitHeard("a", 1);
    int heardFromB = rb.heard().size();
    a.close();
    assertEquals(heardFromB, rb.heard().size(), "b heard something after it closed");
  }

  /** The threads receiving this test's group and port. */
  private long receiveThreads() {
    String suffix = ":" + port + "]";
    return Thread.getAllStackTraces().keySet().stream()
        .filter(t -> t.getName().startsWith("trade-discovery-receive[") && t.getName().endsWith(suffix))
        .count();
  }

  @Test
  void aGivenSchedulerSendsAndCloseEndsItsTasksButNotTheScheduler() throws Exception {
    ScheduledThreadPoolExecutor timer = new ScheduledThreadPoolExecutor(1);
    timer.setRemoveOnCancelPolicy(true);
    try {
      Recorder ra = new Recorder();
      Recorder rb = new Recorder();
      Discovery a = start("alpha", "s3cret", "a", 7001, ra, b -> b.interval(FAST).scheduler(timer));
      start("alpha", "s3cret", "b", 7002, rb, b -> b.interval(FAST));
      rb.awaitHeard("a", 3); // the burst and steady announcements, all sent on the timer
      assertFalse(Thread.getAllStackTraces().keySet().stream()
          .anyMatch(t -> t.getName().equals("trade-discovery[name-a]")), "a thread of its own");
      a.close();
      // The burst's one-shot tasks have run by now; the steady task would stay queued for ever.
      Await.until(Duration.ofSeconds(5), () -> timer.getQueue().isEmpty(),
          "discovery's tasks to leave the timer");
      assertFalse(timer.isShutdown());
      long sent = a.sentCount();
      timer.submit(() -> { }).get(5, TimeUnit.SECONDS); // anything queued meanwhile has run
      assertEquals(sent, a.sentCount());
    } finally {
      timer.shutdownNow();
    }
  }

  private Discovery start(String system, String credentials, String id, int listenPort,
      Recorder recorder, Consumer<Discovery.Builder> tweak) throws IOException {
    Discovery.Builder b = Discovery.builder()
        .systemId(system)
        .credentials(credentials)
        .group(group, port)
        .container(id, "name-" + id)
        .addresses(() -> listenPort == 0 ? List.of() : List.of(address("127.0.0.1", listenPort)))
        .listener(recorder)
        .observer(recorder);
    tweak.accept(b);
    Discovery d = b.start();
    started.add(d);
    return d;
  }
}
