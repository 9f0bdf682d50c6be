package dev.trade.internal.net.link;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.testing.Await;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Who reads a link: a caller reads only while the link's thread lends it reading, and one at a
 * time; the link's thread lends for a linger after a caller last came, and reads again once
 * callers stop, at once when one stops early while others are about, when a caller waits without
 * reading, or when the link closes; a hand-off or the link's end releases it for good.
 */
@Timeout(30)
class ReadRoleTest {
  private static final Duration WAIT = Duration.ofSeconds(10);
  private final ReadRole role = new ReadRole();

  /** The link's thread lends reading on a thread of its own; completes with what lend says. */
  private CompletableFuture<Boolean> lending() {
    CompletableFuture<Boolean> back = CompletableFuture.supplyAsync(role::lend);
    Await.until(WAIT, role::isLent, "the link's thread to lend reading");
    return back;
  }

  @Test
  void aCallerReadsOnlyWhileReadingIsLentAndOneAtATime() throws Exception {
    assertFalse(role.tryTake(), "taken while the link's thread reads");
    role.borrow();
    CompletableFuture<Boolean> back = lending();
    assertTrue(role.tryTake());
    assertTrue(role.isCallerReading());
    assertFalse(role.tryTake(), "a second caller took reading too");
    role.release();
    role.giveBack(false);
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the link's thread reads again");
    assertFalse(role.isLent());
    assertFalse(role.tryTake(), "taken after the link's thread took reading back");
  }

  @Test
  void aCallerThatStopsWhileOthersAreAboutHasTheLinksThreadReadAtOnce() throws Exception {
    role.borrow(); // a caller that goes on borrowing: alone, it would keep reading lent
    role.borrow();
    CompletableFuture<Boolean> back = lending();
    role.giveBack(true); // the other stops early: its reply must not wait
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS));
    assertTrue(role.callerWaits(), "the first caller is still counted");
  }

  /**
   * A caller that called back the peer whose call it serves ends the linger: the link's thread
   * reads again at once and lends no more, on a clock that stands still.
   */
  @Test
  void aCallBackToThePeerEndsTheLingerAtOnce() throws Exception {
    ReadRole still = new ReadRole(ReadRole.MIN_LINGER_NANOS, ReadRole.LINGER_NANOS, () -> 0L);
    still.borrow();
    CompletableFuture<Boolean> back = CompletableFuture.supplyAsync(still::lend);
    Await.until(WAIT, still::isLent, "the link's thread to lend reading");
    still.giveBackCallingBack();
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the link's thread reads again");
    assertFalse(still.shouldLend(), "lends again within a linger that never ends");
  }

  @Test
  void aCallerThatWaitsWithoutReadingHasTheLinksThreadReadAtOnceAndLendNoMoreMeanwhile()
      throws Exception {
    role.borrow(); // a caller about to read: alone, it would keep reading lent
    CompletableFuture<Boolean> back = lending();
    role.parking(); // another waits for its reply, parked: nobody would read it
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the link's thread reads again");
    assertFalse(role.shouldLend(), "lent again while a caller waits without reading");
    role.unparked();
    assertTrue(role.shouldLend(), "not lent to the caller about to read");
  }

  @Test
  void aParkingCallerWakesTheLenderOnceTheCallerThatReadsStops() throws Exception {
    role.borrow();
    CompletableFuture<Boolean> back = lending();
    assertTrue(role.tryTake()); // the lone caller reads
    role.parking(); // a second caller comes and parks
    assertFalse(back.isDone(), "the link's thread read while a caller did");
    role.release(); // the first has its reply
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the link's thread reads again");
  }

  @Test
  void readingIsLentForTheLingerAfterACallerLastCameAndNotBeforeOne() throws Exception {
    long tenMinutes = TimeUnit.MINUTES.toNanos(10);
    ReadRole longLinger = new ReadRole(tenMinutes, tenMinutes, System::nanoTime);
    assertFalse(longLinger.shouldLend(), "lent before any caller came");
    longLinger.borrow();
    longLinger.giveBack(false);
    assertTrue(longLinger.shouldLend(), "a caller that just called, as a control loop's does, "
        + "would find its next reply read by the link's thread");

    long oneMs = TimeUnit.MILLISECONDS.toNanos(1);
    ReadRole shortLinger = new ReadRole(oneMs, oneMs, System::nanoTime);
    shortLinger.borrow();
    shortLinger.giveBack(false);
    Await.until(WAIT, () -> !shortLinger.shouldLend(), "the linger to end");
  }

  /**
   * The linger follows a lone caller's period: twice the last, within its bounds; a caller whose
   * calls are further apart than the most does not borrow, since lending would not reach its next
   * call, and a slow call it makes leaves reading unlent once its reply is read. On a clock of the
   * test's: the periods are exact, whatever the machine does meanwhile.
   */
  @Test
  void theLingerIsTwiceTheCallersLastPeriodWithinItsBoundsAndSlowerCallersDoNotBorrow() {
    long ms = TimeUnit.MILLISECONDS.toNanos(1);
    AtomicLong now = new AtomicLong(1_000 * ms);
    ReadRole role = new ReadRole(ms / 5, 10 * ms, now::get);
    assertFalse(role.lendingPays(), "no lone caller called yet");
    role.touch(); // a lone call, not borrowing
    assertTrue(role.lendingPays(), "called again at once");
    now.addAndGet(10 * ms);
    assertTrue(role.lendingPays(), "called again after the longest linger");
    role.borrow(); // a period of 10 ms: the most
    assertEquals(10 * ms, role.linger());
    role.giveBack(false);
    now.addAndGet(2 * ms);
    assertTrue(role.lendingPays());
    role.borrow(); // a period of 2 ms
    assertEquals(4 * ms, role.linger());
    role.giveBack(false);
    now.addAndGet(ms / 20);
    role.borrow(); // back to back: the least
    assertEquals(ms / 5, role.linger());
    role.giveBack(false);
    assertTrue(role.shouldLend(), "lent within the linger after the caller gave reading back");
    now.addAndGet(ms / 5);
    assertFalse(role.shouldLend(), "lent after the linger");
    now.addAndGet(10 * ms);
    assertFalse(role.lendingPays(), "a caller slower than the longest linger borrows");
    role.touch(); // it calls without borrowing
    assertFalse(role.shouldLend(), "reading is lent after a call that did not borrow");
    now.addAndGet(20 * ms);
    role.borrow(); // a period past the most: lending would not reach the next call
    assertEquals(ms / 5, role.linger());
  }

  @Test
  void closingTakesReadingBackWhileCallersAreAbout() throws Exception {
    role.borrow();
    CompletableFuture<Boolean> back = lending();
    role.closing();
    assertTrue(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS), "the link's thread ends the link");
  }

  @Test
  void aHandOffOrTheEndReleasesTheLinksThread() throws Exception {
    role.borrow();
    CompletableFuture<Boolean> back = lending();
    role.takenOver(); // another thread reads now
    assertFalse(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS));
    back = lending();
    assertTrue(role.tryTake());
    role.ended(); // the caller found the link broken
    assertFalse(back.get(WAIT.toMillis(), TimeUnit.MILLISECONDS));
    assertEquals(false, role.tryTake(), "taken after the end");
  }
}
