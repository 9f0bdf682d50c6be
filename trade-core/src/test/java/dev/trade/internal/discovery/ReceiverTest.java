package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.KEY;
import static dev.trade.internal.discovery.Fixtures.SYSTEM;
import static dev.trade.internal.discovery.Fixtures.announcement;
import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The receive pipeline, packet by packet, without the network (the channel is never bound). */
class ReceiverTest {
  private static final InetSocketAddress FROM =
      new InetSocketAddress(InetAddress.getLoopbackAddress(), 40_000);

  private final Recorder recorder = new Recorder();
  private final AtomicInteger newcomers = new AtomicInteger();
  private final List<Announcement> delivered = new ArrayList<>();
  private Receiver receiver;

  @AfterEach
  void close() {
    if (receiver != null) {
      receiver.close();
    }
  }

  @Test
  void ownRepeatedAndNewAnnouncements() throws IOException {
    receiver = receiver((a, from, answer) -> delivered.add(a));
    byte[] own = announcement("me", 1).encode(KEY);
    receiver.handle(own, own.length, FROM);
    byte[] first = announcement("other", 1).encode(KEY);
    receiver.handle(first, first.length, FROM);
    receiver.handle(first, first.length, FROM);
    byte[] second = announcement("other", 2).encode(KEY);
    receiver.handle(second, second.length, FROM);
    byte[] old = announcement("other", 1, System.currentTimeMillis() - 5000).encode(KEY);
    receiver.handle(old, old.length, FROM);

    assertEquals(List.of(1L, 2L), delivered.stream().map(Announcement::sequence).toList());
    assertEquals(1, newcomers.get(), "only the first announcement of a container is news");
    assertEquals(1L, receiver.dropCounts().get(Reason.OWN));
    assertEquals(1L, receiver.dropCounts().get(Reason.OVERTAKEN), "the first one twice");
    assertEquals(1L, receiver.dropCounts().get(Reason.REPLAYED), "one sent 5 s before");
    assertEquals(1, recorder.drops(Reason.REPLAYED));
    assertEquals(Reason.values().length, receiver.dropCounts().size());
  }

  @Test
  void aFailingListenerDoesNotStopDelivery() throws IOException {
    receiver = receiver((a, from, answer) -> {
      delivered.add(a);
      throw new IllegalStateException("listener bug");
    });
    byte[] first = announcement("other", 1).encode(KEY);
    byte[] second = announcement("other", 2).encode(KEY);
    receiver.handle(first, first.length, FROM);
    receiver.handle(second, second.length, FROM);
    assertEquals(2, delivered.size());
  }

  @Test
  void aPacketFromTheFarPastIsAClockSkewDrop() throws IOException {
    receiver = receiver((a, from, answer) -> delivered.add(a));
    byte[] old = new Announcement(1, SYSTEM, "other", "n", List.of(), 1,
        System.currentTimeMillis() - 3_600_000).encode(KEY);
    receiver.handle(old, old.length, FROM);
    assertEquals(List.of(), delivered);
    assertEquals(1L, receiver.dropCounts().get(Reason.CLOCK_SKEW));
  }

  /**
   * Datagrams handed over wait for the receiver's executor, at most {@link Receiver#MAX_WAITING} of
   * them: a container whose JVM cannot keep up drops the rest, counted, rather than hold an
   * unbounded queue; the ones kept are all handled, in order, once the executor runs.
   */
  @Test
  void datagramsBeyondTheBacklogAreDroppedCountedAndTheRestHandledInOrder() throws IOException {
    List<Runnable> tasks = new ArrayList<>();
    receiver = receiver((a, from, answer) -> delivered.add(a), tasks::add);
    int extra = 5;
    for (int seq = 1; seq <= Receiver.MAX_WAITING + extra; seq++) {
      receiver.offer(announcement("other", seq).encode(KEY), FROM, null);
    }
    assertEquals(1, tasks.size(), "one task queued for the whole backlog");
    assertEquals(List.of(), delivered, "nothing handled on the offering thread");
    for (int i = 0; i < tasks.size(); i++) { // each task queues the next while some wait
      tasks.get(i).run();
    }
    assertEquals(Receiver.MAX_WAITING, delivered.size());
    for (int i = 0; i < delivered.size(); i++) {
      assertEquals(i + 1, delivered.get(i).sequence(), "in the order offered");
    }
    assertEquals((long) extra, receiver.dropCounts().get(Reason.BACKLOG));
    assertEquals(extra, recorder.drops(Reason.BACKLOG));
    // Handled, the backlog is free again.
    receiver.offer(announcement("other", 5_000).encode(KEY), FROM, null);
    tasks.get(tasks.size() - 1).run();
    assertEquals(Receiver.MAX_WAITING + 1, delivered.size());
  }

  private Receiver receiver(Discovery.Listener listener) throws IOException {
    return receiver(listener, Runnable::run);
  }

  private Receiver receiver(Discovery.Listener listener, Executor handler) throws IOException {
    return new Receiver(List.of(), SYSTEM, "me", KEY, listener,
        (a, from) -> newcomers.incrementAndGet(), recorder,
        new ReplayGuard(ReplayGuard.DEFAULT_MAX_SENDERS, Duration.ofSeconds(30)),
        Duration.ofSeconds(60), true, handler);
  }
}
