package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.address;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.testing.Await;
import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * What an interface announces is logged when it changes, not for every packet: a container sends
 * the same announcement every interval and to every newcomer. On loopback with TTL 0, inside the
 * private network namespace CI runs in.
 */
class AnnouncerLogTest {
  private final Logger log = Logger.getLogger(Discovery.class.getName());
  private final List<String> lines = new CopyOnWriteArrayList<>();
  private final List<String> threads = new CopyOnWriteArrayList<>();
  /** The sender's announcements sent when each line was logged (-1 before it exists). */
  private final List<Long> sentWhenLogged = new CopyOnWriteArrayList<>();
  private final Handler capture = new Handler() {
    @Override
    public void publish(LogRecord r) {
      Object[] p = r.getParameters();
      threads.add(Thread.currentThread().getName());
      Discovery d = sender;
      sentWhenLogged.add(d == null ? -1 : d.sentCount());
      lines.add(p == null ? r.getMessage() : r.getMessage() + " " + List.of(p));
    }

    @Override
    public void flush() {}

    @Override
    public void close() {}
  };
  private volatile Discovery sender; // read by the capturing handler
  private Discovery listener;

  @BeforeEach
  void capture() {
    LoopbackMulticast.assumeUsable();
    log.addHandler(capture);
  }

  @AfterEach
  void closeAll() {
    log.removeHandler(capture);
    for (Discovery d : new Discovery[] {sender, listener}) {
      if (d != null) {
        d.close();
      }
    }
  }

  @Test
  void theSameAnnouncementIsLoggedOnceHoweverOftenItIsSent() throws IOException {
    var group = LoopbackMulticast.randomGroup();
    int port = LoopbackMulticast.freePort();
    Recorder heard = new Recorder();
    listener = start(group, port, "listener", 7101, heard);
    sender = start(group, port, "sender", 7102, new Recorder());
    String announcing = "announcing [127.0.0.1:7102] as 'name-sender'";
    Await.until(Duration.ofSeconds(5), () -> lines.stream().anyMatch(l -> l.contains(announcing)),
        "the announcing line");
    long sent = sender.sentCount();
    Await.until(Duration.ofSeconds(5), () -> sender.sentCount() >= sent + 3, "three more intervals");
    assertEquals(1, lines.stream().filter(l -> l.contains(announcing)).count(), lines.toString());
  }

  /**
   * The first log record of a JVM sets up its logging (tens of milliseconds of CPU): the start
   * lines wait until the start burst has been sent, then the announcing thread writes them, the
   * start line first.
   */
  @Test
  void theStartLinesWaitForTheStartBurstThenComeInOrder() throws IOException {
    Recorder recorder = new Recorder();
    sender = start(LoopbackMulticast.randomGroup(), LoopbackMulticast.freePort(), "sender", 7102,
        recorder);
    Await.until(Duration.ofSeconds(5), () -> lines.stream().anyMatch(l -> l.startsWith("Discovery on")),
        "the start lines");
    int start = indexOf("Discovery of");
    int announcing = indexOf("Discovery on");
    assertTrue(start >= 0 && start < announcing, lines.toString());
    assertNotEquals(Thread.currentThread().getName(), threads.get(start));
    assertTrue(sentWhenLogged.get(start) >= Announcer.BURST_MILLIS.length,
        "sent before the start line: " + sentWhenLogged.get(start));
  }

  /** A container closed within its start burst still says what its discovery did. */
  @Test
  void closingWithinTheStartBurstWritesTheLinesHeldBack() throws IOException {
    sender = start(LoopbackMulticast.randomGroup(), LoopbackMulticast.freePort(), "sender", 7102,
        new Recorder());
    sender.close();
    assertTrue(indexOf("Discovery of") >= 0, lines.toString());
  }

  private int indexOf(String prefix) {
    for (int i = 0; i < lines.size(); i++) {
      if (lines.get(i).startsWith(prefix)) {
        return i;
      }
    }
    return -1;
  }

  private static Discovery start(java.net.InetAddress group, int port, String id, int listenPort,
      Recorder recorder) throws IOException {
    return Discovery.builder()
        .systemId("alpha")
        .credentials("s3cret")
        .group(group, port)
        .container(id, "name-" + id)
        .addresses(() -> List.of(address("127.0.0.1", listenPort)))
        .listener(recorder)
        .observer(recorder)
        .interval(Duration.ofMillis(20))
        .start();
  }
}
