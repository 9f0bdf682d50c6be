package org.example.net;

import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.discovery.LoopbackMulticast;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Queue;
import java.util.Set;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.logging.SimpleFormatter;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A container that joins a quiet system larger than a full mesh makes its overlay links at once,
 * with the containers that answered its announcement. Before, it waited until it had heard nearly
 * every container, which in a quiet system is the others' next announcement (BROADCASTINTERVAL,
 * 3 s by default) or three seconds, and lived on its first link meanwhile. The test follows the
 * choices the containers log at DEBUG (docs/configuration.md, Logging).
 */
class NewcomerLinksTest {
  private static final int N = 16;
  private static final TRADEServiceConstraints WHO = new TRADEServiceConstraints().name("whoAmI");
  private static final Pattern HEARD = Pattern.compile("^(\\S+): heard (\\S+) \\(");
  /** A choice of the newcomer's, while it holds or not, and how many it had heard then. */
  private static final Pattern CHOICE =
      Pattern.compile("^newcomer: (?:holding, )?chose \\[([^]]*)] of (?:the )?(\\d+) (heard|that)");
  private static final Pattern DIALLING = Pattern.compile("^newcomer: dialling \\S+ \\((\\S+)\\)");
  private final List<TRADEContainer> containers = new ArrayList<>();
  private final Logger discovery = Logger.getLogger("dev.trade.discovery");
  private final Queue<String> lines = new ConcurrentLinkedQueue<>();
  private final Handler capture = new Handler() {
    private final SimpleFormatter formatter = new SimpleFormatter();

    @Override
    public void publish(LogRecord r) {
      lines.add(formatter.formatMessage(r));
    }

    @Override
    public void flush() {
    }

    @Override
    public void close() {
    }
  };
  private Level level;

  @BeforeEach
  void multicastAndLogs() {
    LoopbackMulticast.assumeUsable();
    level = discovery.getLevel();
    discovery.setLevel(Level.FINE);
    capture.setLevel(Level.FINE);
    discovery.addHandler(capture);
  }

  @AfterEach
  void close() {
    containers.forEach(TRADEContainer::close);
    discovery.removeHandler(capture);
    discovery.setLevel(level);
  }

  @Test
  void aNewcomerMakesItsOverlayLinksAtOnceNotAfterItsHold() throws TRADEException {
    Swarm swarm = Swarm.start(N, containers);
    for (TRADEContainer c : containers) {
      Await.until(Duration.ofSeconds(30), () -> c.getAvailableServices(WHO).size() == N,
          "all services on " + c.getName());
    }
    // Quiet: every container has heard every other one (at the latest at the others' next
    // announcement). A container answers a newcomer by what it has heard.
    Await.until(Duration.ofSeconds(30), () -> heardPairs() == N * (N - 1),
        "every container to have heard every other one");
    TRADEContainer newcomer = swarm.join("newcomer");
    containers.add(newcomer);
    Await.until(Duration.ofSeconds(30), () -> newcomer.getAvailableServices(WHO).size() == N + 1,
        "all services on the newcomer");
    // Its choice once its hold is over. Before, it then dialled the containers of its overlay
    // beyond its first contact; now it dialled them at once, chosen out of those that answered it
    // while it held. (A choice is logged after the dials it makes at once.)
    Await.until(Duration.ofSeconds(30), () -> holdOver(lines) >= 0,
        "the newcomer's choice at the end of its hold");
    List<String> log = new ArrayList<>(lines);
    int last = holdOver(log);
    Set<String> early = new HashSet<>();
    Set<String> dialled = new HashSet<>();
    for (String line : log.subList(0, last)) {
      Matcher c = CHOICE.matcher(line);
      if (c.find()) {
        early.addAll(ids(c.group(1)));
      }
    }
    for (String line : log.subList(0, last)) {
      Matcher d = DIALLING.matcher(line);
      if (d.find() && !early.contains(d.group(1))) {
        dialled.add(d.group(1)); // not chosen before: dialled by the choice at the hold's end
      }
    }
    assertTrue(dialled.isEmpty(), "dialled once the hold was over: " + dialled + ", chosen before: "
        + early + "; " + log);
    Matcher m = CHOICE.matcher(log.get(last));
    assertTrue(m.find());
    assertTrue(ids(m.group(1)).size() < N, "a full mesh: " + m.group(1));
  }

  /** How many (container, container heard) pairs the logs name among the first N containers. */
  private int heardPairs() {
    Set<String> pairs = new HashSet<>();
    for (String line : lines) {
      Matcher m = HEARD.matcher(line);
      if (m.find() && !m.group(1).equals("newcomer") && !m.group(2).equals("newcomer")) {
        pairs.add(m.group(1) + " " + m.group(2));
      }
    }
    return pairs.size();
  }

  /**
   * Where in {@code log} the newcomer's choice at the end of its hold is, or -1: its second choice
   * out of all it heard (the first, at once, is out of its first contact only; those between are
   * made while it holds).
   */
  private static int holdOver(Iterable<String> log) {
    int i = 0;
    int outOfAll = 0;
    for (String line : log) {
      Matcher m = CHOICE.matcher(line);
      if (m.find() && m.group(3).equals("heard") && ++outOfAll == 2) {
        return i;
      }
      i++;
    }
    return -1;
  }

  private static Set<String> ids(String list) {
    Set<String> result = new HashSet<>();
    for (String id : list.split(", ")) {
      if (!id.isBlank()) {
        result.add(id.trim());
      }
    }
    return result;
  }
}
