package dev.trade.internal.discovery;

import static org.junit.jupiter.api.Assertions.fail;

import dev.trade.internal.discovery.BadPacketException.Reason;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

/**
 * A discovery listener and observer that records everything, and waits for a condition on what it
 * recorded with a deadline. Thread-safe: the receive thread records, the test thread waits.
 */
final class Recorder implements Discovery.Listener, Receiver.Observer {
  static final long DEADLINE_MILLIS = 5000;

  private final List<Announcement> heard = new ArrayList<>();
  private final List<InetAddress> from = new ArrayList<>();
  private final List<Boolean> answers = new ArrayList<>();
  private final Map<Reason, Integer> drops = new EnumMap<>(Reason.class);
  private int ignored;

  @Override
  public synchronized void heard(Announcement a, InetAddress source, boolean answer) {
    heard.add(a);
    from.add(source);
    answers.add(answer);
    notifyAll();
  }

  @Override
  public synchronized void dropped(Reason reason) {
    drops.merge(reason, 1, Integer::sum);
    notifyAll();
  }

  @Override
  public synchronized void ignored() {
    ignored++;
    notifyAll();
  }

  synchronized int heardFrom(String containerId) {
    return count(a -> a.containerId().equals(containerId));
  }

  synchronized int count(Predicate<Announcement> p) {
    return (int) heard.stream().filter(p).count();
  }

  synchronized List<Announcement> heard() {
    return List.copyOf(heard);
  }

  /** Whether each announcement {@link #heard()} lists came as an answer, in the same order. */
  synchronized List<Boolean> answers() {
    return List.copyOf(answers);
  }

  synchronized List<InetAddress> sources() {
    return List.copyOf(from);
  }

  synchronized int drops(Reason reason) {
    return drops.getOrDefault(reason, 0);
  }

  synchronized int dropsOtherThanOwn() {
    return drops.entrySet().stream().filter(e -> e.getKey() != Reason.OWN)
        .mapToInt(Map.Entry::getValue).sum();
  }

  synchronized int ignoredCount() {
    return ignored;
  }

  /** Waits until {@code condition} holds, at most {@link #DEADLINE_MILLIS}; fails naming it. */
  synchronized void await(String what, BooleanSupplier condition) {
    long deadline = System.nanoTime() + DEADLINE_MILLIS * 1_000_000;
    while (!condition.getAsBoolean()) {
      long left = (deadline - System.nanoTime()) / 1_000_000;
      if (left <= 0) {
        fail("Not within " + DEADLINE_MILLIS + " ms: " + what + "; heard " + heard + ", drops "
            + drops + ", ignored " + ignored);
      }
      try {
        wait(left);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
        fail("interrupted while waiting until " + what);
      }
    }
  }

  /** Waits until an announcement from {@code containerId} has been heard {@code n} times. */
  void awaitHeard(String containerId, int n) {
    await("heard '" + containerId + "' " + n + " times", () -> heardFrom(containerId) >= n);
  }

  /** Waits until an announcement from {@code containerId} listing {@code address} is heard. */
  void awaitHeardAt(String containerId, InetSocketAddress address) {
    await("heard '" + containerId + "' at " + address, () -> count(
        a -> a.containerId().equals(containerId) && a.addresses().contains(address)) > 0);
  }

  void awaitDrops(Reason reason, int n) {
    await(n + " drops for " + reason, () -> drops(reason) >= n);
  }
}
