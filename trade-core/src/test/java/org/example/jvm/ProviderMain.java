package org.example.jvm;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.example.jvm.RemoteTypes.ArmJammedException;
import org.example.jvm.RemoteTypes.Gripper;
import org.example.jvm.RemoteTypes.Plan;
import org.example.jvm.RemoteTypes.Pose;
import org.example.jvm.RemoteTypes.Waypoint;
import org.example.jvm.secret.Secrets;

/**
 * A provider process for the cross-JVM tests: builds a container from {@code KEY=VALUE} arguments
 * (the keys of {@code trade.properties}), registers {@link Services} in group {@code provider},
 * prints {@code READY <ip@port>} (the first listen address, or {@code -} when it does not listen),
 * and runs until its standard input ends or it is killed.
 *
 * <p>Also prints {@code SLOW <millis>} when a {@link Services#slow} call starts, so that a test
 * knows the call is in progress before it acts.
 */
public final class ProviderMain {
  /** Counted down when standard input ends: wakes slow calls and lets the process exit. */
  private static final CountDownLatch STOPPING = new CountDownLatch(1);

  private ProviderMain() {}

  /** Starts a provider JVM with these settings ({@code KEY=VALUE}) and extra class path entries. */
  static JvmProcess launch(List<Path> extraClassPath, String... settings) throws IOException {
    return JvmProcess.start(ProviderMain.class, extraClassPath, settings);
  }

  /** The {@code ip@port} of a {@code READY} line. */
  static String address(String readyLine) {
    return readyLine.substring("READY ".length()).trim();
  }

  /** How many services {@link Services} provides. */
  static int serviceCount() {
    return (int) Arrays.stream(Services.class.getMethods())
        .filter(m -> m.isAnnotationPresent(TRADEService.class)).count();
  }

  public static void main(String[] args) throws Exception {
    TRADEContainer.Builder builder = TRADEContainer.builder();
    for (String a : args) {
      int eq = a.indexOf('=');
      if (eq < 0) {
        throw new IllegalArgumentException("expected KEY=VALUE, got " + a);
      }
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    try (TRADEContainer container = builder.build()) {
      container.registerAllServices(new Services(), "provider");
      List<String> addresses = container.getServerAddresses();
      System.out.println("READY " + (addresses.isEmpty() ? "-" : addresses.get(0)));
      System.out.flush();
      while (System.in.read() >= 0) {
        // Input only tells us when to stop.
      }
      STOPPING.countDown();
    }
    System.exit(0);
  }

  /** The provided services: echoes for every value kind, failures, a callback and a slow call. */
  public static final class Services {
    /** How many times {@link #mix} ran: a call run twice would count twice. */
    private final AtomicLong mixed = new AtomicLong();

    @TRADEService
    public Object echo(Object value) {
      return value;
    }

    /** The class the value has after decoding here, so that tests see both directions. */
    @TRADEService
    public String typeOf(Object value) {
      return value == null ? "null" : value.getClass().getName();
    }

    @TRADEService
    public boolean not(boolean b) {
      return !b;
    }

    @TRADEService
    public byte negateByte(byte b) {
      return (byte) -b;
    }

    @TRADEService
    public short negateShort(short s) {
      return (short) -s;
    }

    @TRADEService
    public int negateInt(int i) {
      return -i;
    }

    @TRADEService
    public long negateLong(long l) {
      return -l;
    }

    @TRADEService
    public float halveFloat(float f) {
      return f / 2;
    }

    @TRADEService
    public double halveDouble(double d) {
      return d / 2;
    }

    @TRADEService
    public char nextChar(char c) {
      return (char) (c + 1);
    }

    @TRADEService
    public String upper(String s) {
      return s == null ? null : s.toUpperCase(Locale.ROOT);
    }

    @TRADEService
    public byte[] reverseBytes(byte[] data) {
      byte[] r = new byte[data.length];
      for (int i = 0; i < data.length; i++) {
        r[i] = data[data.length - 1 - i];
      }
      return r;
    }

    @TRADEService
    public String[] reverseStrings(String[] words) {
      String[] r = new String[words.length];
      for (int i = 0; i < words.length; i++) {
        r[i] = words[words.length - 1 - i];
      }
      return r;
    }

    @TRADEService
    public Pose[] poses(int n) {
      Pose[] r = new Pose[n];
      for (int i = 0; i < n; i++) {
        r[i] = new Pose(i, -i, i / 10.0, "map");
      }
      return r;
    }

    @TRADEService
    public Pose move(Pose p, double dx) {
      return new Pose(p.x() + dx, p.y(), p.theta(), p.frame());
    }

    @TRADEService
    public Gripper toggle(Gripper g) {
      return g == Gripper.OPEN ? Gripper.CLOSED : Gripper.OPEN;
    }

    @TRADEService
    public Plan plan(String name, List<Pose> steps, Map<String, Gripper> grips) {
      return new Plan(name, steps, grips, Set.of(steps.size()));
    }

    @TRADEService
    public Waypoint renamed(Waypoint w, String label) {
      w.label = label;
      return w;
    }

    /** Calls the service {@code callback} (of whichever container) with {@code argument}. */
    @TRADEService
    public String callBack(TRADEServiceInfo callback, String argument) throws TRADEException {
      return callback.call(String.class, argument);
    }

    @TRADEService
    public TRADEServiceInfo echoInfo(TRADEServiceInfo info) {
      return info;
    }

    @TRADEService
    public List<String> describeInfo(TRADEServiceInfo info) {
      return List.of(info.serviceString, info.getContainerName(), String.valueOf(info.isLocal()));
    }

    /** A value of a type the test JVM's consumer does not allow. */
    @TRADEService
    public Object secretCode() {
      return new Secrets.Code("1234");
    }

    /**
     * Throws: {@code state}, an IllegalStateException; {@code jammed}, a checked user exception with
     * a cause; {@code secret}, an exception in a package the consumer does not allow; anything else
     * is the name of a RuntimeException class with a (String) constructor, loaded here.
     */
    @TRADEService
    public void fail(String kind) throws Exception {
      switch (kind) {
        case "state":
          throw new IllegalStateException("jammed");
        case "jammed":
          throw new ArmJammedException("gripper 2 jammed", new IOException("sensor offline"));
        case "secret":
          throw new Secrets.SecretException("the code is 1234");
        default:
          throw (RuntimeException) Class.forName(kind).getConstructor(String.class)
              .newInstance("thrown by " + kind);
      }
    }

    /** A reply that only a run with {@code x} can give: {@code x:hex(scramble(x))}. */
    @TRADEService
    public String mix(long x) {
      mixed.incrementAndGet();
      return x + ":" + Long.toHexString(ConcurrentCallersTest.scramble(x));
    }

    /** How many times {@link #mix} has run. */
    @TRADEService
    public long mixed() {
      return mixed.get();
    }

    /**
     * Blocks for {@code millis} (or until the provider stops) to stand for a long computation;
     * prints {@code SLOW <millis>} first. Returns {@code millis}, so that each reply names its call.
     */
    @TRADEService
    public long slow(long millis) throws InterruptedException {
      System.out.println("SLOW " + millis);
      System.out.flush();
      STOPPING.await(millis, TimeUnit.MILLISECONDS);
      return millis;
    }
  }
}
