package dev.trade.internal.discovery;

import static dev.trade.internal.discovery.Fixtures.address;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.logging.Handler;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.example.net.Await;
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
  private final Handler capture = new Handler() {
    @Override
    public void publish(LogRecord r) {
      Object[] p = r.getParameters();
      threads.add(Thread.currentThread().getName());
      lines.add(p == null ? r.getMessage() : r.getMessage() + " " + List.of(p));
    }

    @Override
    public void flush() {}

    @Override
    public void close() {}
  };
  private Discovery sender;
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
    heard.awaitHeard("sender", Announcer.BURST_MILLIS.length + 3); // burst, answer and intervals
    String announcing = "announcing [127.0.0.1:7102] as 'name-sender'";
    assertEquals(1, lines.stream().filter(l -> l.contains(announcing)).count(), lines.toString());
  }

  /**
   * The first log record of a JVM sets up its logging (tens of milliseconds): the start line is
   * written by the announcing thread, after the first announcement, not by the one that builds.
   */
  @Test
  void theStartLineIsWrittenByTheAnnouncingThreadAfterTheFirstAnnouncement() throws IOException {
    Recorder recorder = new Recorder();
    sender = start(LoopbackMulticast.randomGroup(), LoopbackMulticast.freePort(), "sender", 7102,
        recorder);
    Await.until(Duration.ofSeconds(5), () -> lines.stream().anyMatch(l -> l.startsWith("Discovery of")),
        "the start line");
    int start = indexOf("Discovery of");
    int announcing = indexOf("Discovery on");
    assertNotEquals(Thread.currentThread().getName(), threads.get(start));
    assertTrue(announcing >= 0 && announcing < start, lines.toString());
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
