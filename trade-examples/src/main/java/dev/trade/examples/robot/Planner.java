package dev.trade.examples.robot;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADELock;
import dev.trade.TRADELockInfo;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import java.io.PrintStream;
import java.time.Duration;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;

/**
 * A task component: it fetches a cup for someone in the kitchen, using whatever robot parts it
 * finds in its groups at run time. It knows no addresses and no container names: it asks for
 * services by name, argument types and group, learns about arrivals and departures through
 * {@code joined} and {@code left} notifications, and carries on when a part dies.
 *
 * <p>The scenario ({@link #run()}):
 *
 * <ol>
 *   <li>waits until an arm ({@code moveTo}, {@code openGripper}, {@code closeGripper}), a camera
 *       ({@code checkFor}), a head ({@code pan}, {@code tilt}) and a battery ({@code level}) have
 *       joined its groups;
 *   <li>asks for the battery's {@code level()} with a {@code once} notification (a call that does
 *       not block the planner; the result arrives at {@link #batteryReport}) and watches the
 *       battery with a {@code when} notification: {@code isLow()}, asked every
 *       {@value #BATTERY_PERIOD_MS} ms in the battery's own container, calls {@link #batteryLow}
 *       the first time it is true;
 *   <li>picks up the cup the camera sees, holding a lock on the head while it looks; it releases
 *       the head once another process (the lookout) waits for it;
 *   <li>says {@code waiting for navigation to join} and waits for a {@code goTo} service, then
 *       drives to the kitchen;
 *   <li>says {@code watching for people} and keeps asking the camera, through the handle it got in
 *       step 1, until that handle fails with {@link TRADEServiceUnavailableException} (the camera's
 *       process was killed) and the camera's {@code left} notification has arrived;
 *   <li>carries on with what is left: puts the cup down without looking, cancels the battery watch
 *       if the battery never ran low, and says {@code scenario complete}.
 * </ol>
 *
 * Every wait has a deadline; a missed one ends the scenario with a line saying what was missing.
 *
 * <p>Its callbacks are services, as TRADE requires: its container registers it (in no group) for
 * its notifications and deregisters it when the last one is cancelled. Safe for concurrent use
 * (callbacks arrive on the container's delivery threads).
 */
public final class Planner {
  private static final Duration WAIT = Duration.ofSeconds(20);
  private static final long WATCH_PERIOD_MS = 100;
  private static final long BATTERY_PERIOD_MS = 100;
  private static final Pose CARRY = new Pose(0.10, 0.00, 0.40);
  private static final Pose COUNTER = new Pose(0.45, 0.30, 0.05);

  private final TRADEContainer trade;
  private final String[] groups;
  private final PrintStream out;
  // Signalled on every joined and left, so that waits re-check the system at once.
  private final Object changes = new Object();
  private final Set<TRADEServiceInfo> departed = ConcurrentHashMap.newKeySet();
  private volatile boolean batteryLow;

  /**
   * A planner that uses the services of {@code groups} (a service must be in all of them).
   *
   * @throws IllegalArgumentException if {@code groups} is empty: without a group the planner
   *     could pick up the parts of any robot in the system
   */
  public Planner(TRADEContainer trade, Collection<String> groups, PrintStream out) {
    this.trade = Objects.requireNonNull(trade, "trade == null");
    this.groups = groups.toArray(new String[0]);
    this.out = Objects.requireNonNull(out, "out == null");
    if (this.groups.length == 0) {
      throw new IllegalArgumentException("the planner needs at least one group");
    }
  }

  /** The {@code joined} callback: a service of the planner's groups became available. */
  @TRADEService
  public void serviceJoined(TRADEServiceInfo service) {
    out.println("joined: " + service.serviceString + " @ " + service.getContainerName());
    signal();
  }

  /** The {@code left} callback: a service of the planner's groups went away. */
  @TRADEService
  public void serviceLeft(TRADEServiceInfo service) {
    departed.add(service);
    out.println("left: " + service.serviceString + " @ " + service.getContainerName());
    signal();
  }

  /** The {@code once} callback: the battery's level, read without blocking the planner. */
  @TRADEService
  public void batteryReport(int percent) {
    out.println("battery at " + percent + "% (a once notification's result)");
  }

  /** The {@code when} callback: the battery ran low. */
  @TRADEService
  public void batteryLow() {
    batteryLow = true;
    out.println("battery low: the when notification fired; time to go back to the dock");
  }

  private void signal() {
    synchronized (changes) {
      changes.notifyAll();
    }
  }

  /**
   * Runs the scenario described in the class comment.
   *
   * @return whether it was completed; when not, a line saying why has been printed
   * @throws InterruptedException if the thread was interrupted while waiting
   */
  public boolean run() throws InterruptedException {
    try {
      scenario();
      out.println("scenario complete");
      return true;
    } catch (ScenarioFailure | TRADEException e) {
      out.println("scenario failed: " + e.getClass().getSimpleName() + ": " + e.getMessage());
      return false;
    }
  }

  private void scenario() throws TRADEException, ScenarioFailure, InterruptedException {
    out.println("looking for services in " + List.of(groups));
    TRADEServiceConstraints mine = new TRADEServiceConstraints().inGroups(groups);
    trade.requestNotification(this, "left", mine, null, "serviceLeft");
    trade.registerNotificationNowOrWhenJoined(this, mine, "serviceJoined");

    // 1. Find the parts by what they can do, wherever they run.
    TRADEServiceInfo checkFor = await("a camera", need("checkFor", String.class));
    TRADEServiceInfo moveTo = await("an arm", need("moveTo", Pose.class));
    TRADEServiceInfo open = await("a gripper", need("openGripper", int.class));
    TRADEServiceInfo close = await("a gripper", need("closeGripper"));
    TRADEServiceInfo pan = await("a head", need("pan", double.class));
    TRADEServiceInfo tilt = await("a head", need("tilt", double.class));
    TRADEServiceInfo level = await("a battery", need("level"));
    out.println("found a camera on " + checkFor.getContainerName() + ", an arm on "
        + moveTo.getContainerName() + ", a head on " + pan.getContainerName()
        + " and a battery on " + level.getContainerName());

    // 2. Ask the battery without waiting for it, and watch it where it is.
    trade.requestNotification(this, "once", null, List.of(level), "batteryReport");
    TRADEServiceInfo isLow = await("a battery", need("isLow"));
    trade.requestNotification(this, "when", BATTERY_PERIOD_MS, List.of(isLow), "batteryLow");
    out.println("watching the battery: when isLow() (every " + BATTERY_PERIOD_MS + " ms, on "
        + isLow.getContainerName() + ") then batteryLow()");

    // 3. Fetch the cup, holding the head while looking (a lock over services of the head's
    // container: nobody else turns it meanwhile).
    Detection cup;
    try (TRADELock look = trade.lock(List.of(pan, tilt), WAIT)) {
      out.println("holding the head while looking for the cup");
      pan.call(look.getId(), double.class, -20.0);
      tilt.call(look.getId(), double.class, -35.0);
      cup = checkFor.call(Detection.class, "cup");
      out.println("the camera sees " + cup);
      awaitWaiterFor(pan);
    }
    out.println("released the head");
    if (!cup.found()) {
      throw new ScenarioFailure("no cup in sight");
    }
    moveTo.call(Pose.class, cup.pose());
    open.call(boolean.class, 40);
    close.call(void.class);
    moveTo.call(Pose.class, CARRY);
    out.println("picked up the cup");

    // 4. Navigation is not there yet; it is noticed when it joins.
    out.println("waiting for navigation to join");
    TRADEServiceInfo goTo = await("navigation", need("goTo", String.class));
    out.println("navigation is on " + goTo.getContainerName() + "; driving to the kitchen");
    goTo.call(boolean.class, "kitchen");

    // 5. Keep using the camera through the old handle until it fails.
    out.println("watching for people (checkFor every " + WATCH_PERIOD_MS + " ms)");
    watchUntilGone(checkFor);

    // 6. Carry on with what is left.
    Set<String> left = new LinkedHashSet<>();
    for (TRADEServiceInfo s : trade.getAvailableServices(new TRADEServiceConstraints().inGroups(groups))) {
      left.add(s.getContainerName());
    }
    out.println("carrying on with what is left in " + List.of(groups) + ": " + left);
    if (!trade.getAvailableServices(need("checkFor", String.class)).isEmpty()) {
      throw new ScenarioFailure("a camera is still there; the failure did not happen");
    }
    out.println("no camera left: putting the cup down on the counter without looking");
    pan.waitingForLock().call(double.class, 0.0); // the lookout may still hold the head
    moveTo.call(Pose.class, COUNTER);
    open.call(boolean.class, 20);
    out.println("cup delivered; battery at " + level.call(int.class) + "%");
    if (!batteryLow) {
      trade.cancelNotification(this, "when", null);
      out.println("the battery never ran low: battery watch cancelled");
    }
  }

  /**
   * Waits until another process's lock request waits for {@code service}, seen through the locks
   * every container lists (introspection), and names it; gives up after {@link #WAIT}.
   */
  private void awaitWaiterFor(TRADEServiceInfo service) throws TRADEException, InterruptedException {
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (System.nanoTime() - deadline < 0) {
      for (TRADELockInfo i : trade.getLocks()) {
        if (!i.isHolding() && i.getService().equals(service)) {
          out.println("container " + i.getContainerName() + " waits for the head since "
              + i.getSince() + ": releasing it");
          return;
        }
      }
      waitForChange(deadline, WATCH_PERIOD_MS);
    }
    out.println("nobody asked for the head");
  }

  /**
   * Calls {@code checkFor} until it fails as unavailable, then waits for its {@code left}
   * notification (whichever comes first, both must come).
   */
  private void watchUntilGone(TRADEServiceInfo checkFor)
      throws TRADEException, ScenarioFailure, InterruptedException {
    long deadline = System.nanoTime() + WAIT.toNanos();
    while (true) {
      try {
        checkFor.call(Detection.class, "person");
      } catch (TRADEServiceUnavailableException e) {
        out.println("the camera's handle failed: " + e.getClass().getSimpleName() + ": "
            + e.getMessage());
        break;
      }
      if (!waitForChange(deadline, WATCH_PERIOD_MS)) {
        throw new ScenarioFailure("the camera did not fail within " + WAIT.toSeconds() + " s");
      }
    }
    while (!departed.contains(checkFor)) {
      if (!waitForChange(deadline, Long.MAX_VALUE)) {
        throw new ScenarioFailure("no 'left' notification for " + checkFor + " within "
            + WAIT.toSeconds() + " s");
      }
    }
  }

  /**
   * Waits for a joined or left notification, at most {@code maxMillis} and never past
   * {@code deadline}.
   *
   * @return false if the deadline has passed
   */
  private boolean waitForChange(long deadline, long maxMillis) throws InterruptedException {
    long remaining = deadline - System.nanoTime();
    if (remaining <= 0) {
      return false;
    }
    synchronized (changes) {
      TimeUnit.NANOSECONDS.timedWait(changes,
          Math.min(remaining, TimeUnit.MILLISECONDS.toNanos(maxMillis)));
    }
    return true;
  }

  /** The preferred service matching {@code constraints}, waiting until one joins. */
  private TRADEServiceInfo await(String what, TRADEServiceConstraints constraints)
      throws ScenarioFailure, InterruptedException {
    long deadline = System.nanoTime() + WAIT.toNanos();
    synchronized (changes) {
      // Checked under the lock the callbacks signal on, so no join between check and wait is lost.
      while (true) {
        Collection<TRADEServiceInfo> found = trade.getAvailableServices(constraints);
        if (!found.isEmpty()) {
          return found.iterator().next();
        }
        long remaining = deadline - System.nanoTime();
        if (remaining <= 0) {
          throw new ScenarioFailure("no " + what + " (" + constraints + ") joined within "
              + WAIT.toSeconds() + " s");
        }
        TimeUnit.NANOSECONDS.timedWait(changes, remaining);
      }
    }
  }

  private TRADEServiceConstraints need(String name, Class<?>... argTypes) {
    return new TRADEServiceConstraints().name(name).argTypes(argTypes).inGroups(groups);
  }

  /** A step of the scenario could not be done. */
  private static final class ScenarioFailure extends Exception {
    ScenarioFailure(String message) {
      super(message);
    }
  }
}
