package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.assertEquals;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.text.MessageFormat;
import java.util.ArrayList;
import java.util.List;
import java.util.ResourceBundle;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;

/** What a person reading the log learns about dropped packets, and how often. */
class DropsTest {
  private static final long SECOND = 1_000_000_000L;

  private final RecordingLogger log = new RecordingLogger();
  private final Drops drops = new Drops(log, "alpha", 60 * SECOND);

  @Test
  void namesTheOtherSystemOncePerIntervalWithTheCountHeldBack() throws Exception {
    InetAddress from = InetAddress.getByName("10.0.0.5");
    BadPacketException foreign = new BadPacketException(Reason.FOREIGN_SYSTEM,
        "other system id 'beta'");
    drops.record(foreign, from, 0);
    drops.record(foreign, from, 10 * SECOND);
    drops.record(foreign, from, 20 * SECOND);
    drops.record(foreign, from, 61 * SECOND);
    String line = "Ignoring announcements from 10.0.0.5: other system id 'beta' (this container's"
        + " is 'alpha'); set the same TRADESYSID to join them";
    assertEquals(List.of("INFO " + line, "INFO " + line + " (2 more since the last report)"),
        log.above(Level.DEBUG));
    assertEquals(4, log.at(Level.DEBUG).size());
    assertEquals(4L, drops.counts().get(Reason.FOREIGN_SYSTEM));
  }

  @Test
  void badHmacIsAWarningThatSuspectsTheCredentials() throws Exception {
    drops.record(new BadPacketException(Reason.BAD_HMAC, "bad HMAC: wrong CREDENTIALS?"),
        InetAddress.getByName("10.0.0.6"), 0);
    assertEquals(List.of("WARNING Ignoring announcements from 10.0.0.6: bad HMAC: wrong"
        + " CREDENTIALS? The system id 'alpha' matches, so the sender has other CREDENTIALS, or"
        + " the packet was forged or damaged"), log.above(Level.DEBUG));
  }

  @Test
  void eachSenderAndReasonIsReportedSeparately() throws Exception {
    BadPacketException magic = new BadPacketException(Reason.BAD_MAGIC, "no TRADE magic bytes");
    drops.record(magic, InetAddress.getByName("10.0.0.5"), 0);
    drops.record(magic, InetAddress.getByName("10.0.0.7"), 0);
    drops.record(new BadPacketException(Reason.TOO_SHORT, "3 bytes, less than 60"),
        InetAddress.getByName("10.0.0.5"), 0);
    assertEquals(List.of(
        "INFO Ignoring datagrams from 10.0.0.5 on the discovery port: not TRADE announcements"
            + " (no TRADE magic bytes); does another program use it?",
        "INFO Ignoring datagrams from 10.0.0.7 on the discovery port: not TRADE announcements"
            + " (no TRADE magic bytes); does another program use it?",
        "INFO Ignoring datagrams from 10.0.0.5 on the discovery port: not TRADE announcements"
            + " (3 bytes, less than 60); does another program use it?"), log.above(Level.DEBUG));
  }

  @Test
  void ownPacketsAreOnlyCounted() throws Exception {
    drops.record(new BadPacketException(Reason.OWN, "our own announcement"),
        InetAddress.getLoopbackAddress(), 0);
    assertEquals(List.of(), log.above(Level.DEBUG));
    assertEquals(1L, drops.counts().get(Reason.OWN));
    assertEquals(0L, drops.counts().get(Reason.BAD_HMAC));
  }

  @Test
  void overtakenPacketsAreOnlyCountedWhileReplaysAreReported() throws Exception {
    InetAddress from = InetAddress.getByName("10.0.0.5");
    drops.record(new BadPacketException(Reason.OVERTAKEN, "sequence 5 of container 'arm' (c1),"
        + " already at 6"), from, 0);
    assertEquals(List.of(), log.above(Level.DEBUG));
    assertEquals(1L, drops.counts().get(Reason.OVERTAKEN));
    drops.record(new BadPacketException(Reason.REPLAYED, "sequence 5 of container 'arm' (c1),"
        + " already at 6"), from, 0);
    assertEquals(List.of("INFO Ignoring announcements from 10.0.0.5: replayed: sequence 5 of"
        + " container 'arm' (c1), already at 6"), log.above(Level.DEBUG));
  }

  /** Keeps "LEVEL message" lines, formatted as java.util.logging would. */
  private static final class RecordingLogger implements Logger {
    private final List<Level> levels = new ArrayList<>();
    private final List<String> lines = new ArrayList<>();

    List<String> above(Level level) {
      List<String> out = new ArrayList<>();
      for (int i = 0; i < lines.size(); i++) {
        if (levels.get(i).getSeverity() > level.getSeverity()) {
          out.add(levels.get(i).getName() + " " + lines.get(i));
        }
      }
      return out;
    }

    List<String> at(Level level) {
      List<String> out = new ArrayList<>();
      for (int i = 0; i < lines.size(); i++) {
        if (levels.get(i) == level) {
          out.add(lines.get(i));
        }
      }
      return out;
    }

    @Override
    public String getName() {
      return "test";
    }

    @Override
    public boolean isLoggable(Level level) {
      return true;
    }

    @Override
    public void log(Level level, ResourceBundle bundle, String msg, Throwable thrown) {
      levels.add(level);
      lines.add(msg);
    }

    @Override
    public void log(Level level, ResourceBundle bundle, String format, Object... params) {
      levels.add(level);
      lines.add(params == null || params.length == 0 ? format
          : MessageFormat.format(format, params));
    }

    @Override
    public void log(Level level, Supplier<String> msg) {
      log(level, null, msg.get(), (Throwable) null);
    }
  }
}
