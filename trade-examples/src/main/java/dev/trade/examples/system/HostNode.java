package dev.trade.examples.system;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADELock;
import dev.trade.TRADELockInfo;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;

/**
 * One container of the multi-host system tests (src/system-tests): it plays a host of its own,
 * registers a {@code whereAmI()} service in the group {@code host-<name>} and in {@code multihost},
 * reports joined and left services of other containers, and calls services when told to.
 *
 * <p>Usage: {@code HostNode <name> [KEY=VALUE ...]}, where each {@code KEY=VALUE} is a TRADE setting
 * (docs/configuration.md), for example {@code DISCOVERYRANGE=subnet DISCOVERYINTERFACES=veth-a}.
 * Without settings the container discovers and announces in range {@code localhost}.
 *
 * <p>It prints one line per event on standard output, each ending in {@code t=<epoch ms>}:
 *
 * <pre>
 * READY A id=&lt;container id&gt; pid=&lt;pid&gt; listening=[0.0.0.0@41247] t=...
 * JOINED whereAmI()@B t=...
 * LEFT whereAmI()@B t=...
 * CALLED host-B -> B on [10.200.2.2] in 3 ms t=...
 * CALL-FAILED host-B TRADEServiceNotFoundException: ... t=...
 * SERVING whereAmIAfter(5000) t=...
 * LOCKED 6f3e... A=12,C=7 t=...
 * UNDER-LOCK host-A -> A t=...
 * UNDER-LOCK-FAILED host-A TRADELockedException: ... t=...
 * ACTUATED by B t=...
 * LOCKS actuate(java.lang.String)@A=B:6f3e...:12 t=...
 * RELEASED 6f3e... t=...
 * NEIGHBOURS &lt;id&gt;,&lt;id&gt; t=...
 * ADMIN describeContainer@B -> {id=..., name=B, ...} t=...
 * ADMIN-FAILED shutdown@A TRADENotAuthorizedException: Not authorized: ... t=...
 * BYE t=...
 * </pre>
 *
 * <p>It reads commands, one a line, from standard input: {@code call <group>} (find
 * {@code whereAmI()} in that group and call it), {@code call <group> <ms>} (the same with
 * {@code whereAmIAfter(ms)}, which answers after that delay and prints {@code SERVING} where it
 * runs), {@code bulk <group> <calls> <KiB>} (that many calls of {@code length(byte[])} at once,
 * each with an argument of that size; prints {@code BULK <group> <calls> answered in <ms> ms} or
 * {@code BULK-FAILED <group> <n> of <calls>: <first failure>}), {@code neighbours},
 * {@code lock <group>,<group>... <ms>} (lock {@code actuate(String)} of each group at once,
 * waiting up to that long; prints {@code LOCKED <id> <container>=<fencing token>,...} or
 * {@code LOCK-FAILED}), {@code under <group>} (call {@code actuate(String)} in that group under
 * the lock taken last, or without a lock if none; the service prints {@code ACTUATED by <caller>}
 * where it runs), {@code release} (release the lock taken last), {@code locks} (every holder:
 * service, container, holder's container, lock id, token),
 * {@code admin <credentials> <container> <operation> [<argument>]} (calls that container's
 * middleware service, docs/middleware-services.md, as {@code <principal>:<secret>}, or anonymously
 * for {@code -}; {@code startProvider} takes a class name and registers it in the group
 * {@code lamp}; prints {@code ADMIN} with the result or {@code ADMIN-FAILED} with the typed
 * failure), and {@code quit}. Calls, lock and admin commands run on threads of their own. At the end
 * of its input it closes the container and exits, so that it never outlives the test that drives
 * it. Logs go to standard error.
 */
public final class HostNode {
  private static final Duration CALL_TIMEOUT = Duration.ofSeconds(5);
  private static final Duration BULK_TIMEOUT = Duration.ofSeconds(60);

  /** The service every node provides: where it runs. */
  public static final class Place {
    private final String name;

    Place(String name) {
      this.name = name;
    }

    @TRADEService
    public String whereAmI() {
      return name + " on " + ipv4Addresses();
    }

    /** The length of {@code data}: a call whose argument is as large as one likes. */
    @TRADEService
    public int length(byte[] data) {
      return data.length;
    }

    /** As {@link #whereAmI()}, answering after {@code millis} ms: a call that is in flight a while. */
    @TRADEService
    public String whereAmIAfter(long millis) throws InterruptedException {
      say("SERVING whereAmIAfter(" + millis + ")");
      Thread.sleep(millis);
      return whereAmI();
    }
  }

  /** An effector to lock: it says where it runs and for whom. */
  public static final class Effector {
    private final String name;

    Effector(String name) {
      this.name = name;
    }

    /** Acts for {@code by} (the caller's name) and answers with this host's name. */
    @TRADEService
    public String actuate(String by) {
      say("ACTUATED by " + by);
      return name;
    }
  }

  /**
   * A provider an administrator may start in a node by class name (its PROVIDERCLASSES allows it
   * in the system tests); its service is not {@code whereAmI()}, so the nodes do not report it.
   */
  public static final class Lamp {
    @TRADEService
    public String light() {
      return "lit";
    }
  }

  /** Receives joined and left notifications; callbacks are services. */
  public static final class Watcher {
    @TRADEService
    public void joined(TRADEServiceInfo info) {
      if (!info.isLocal()) {
        say("JOINED " + info.serviceString + "@" + info.getContainerName());
      }
    }

    @TRADEService
    public void left(TRADEServiceInfo info) {
      if (!info.isLocal()) {
        say("LEFT " + info.serviceString + "@" + info.getContainerName());
      }
    }
  }

  /** The lock taken last by the {@code lock} command, until released. */
  private static volatile TRADELock lock;

  private HostNode() {}

  public static void main(String[] args) throws Exception {
    if (args.length < 1 || args[0].contains("=")) {
      System.err.println("usage: HostNode <name> [KEY=VALUE ...]");
      System.exit(2);
    }
    String name = args[0];
    Map<String, String> settings = new TreeMap<>();
    settings.put("CONTAINERNAME", name);
    settings.put("STARTDISCOVERY", "true");
    settings.put("STARTBROADCAST", "true");
    for (int i = 1; i < args.length; i++) {
      int eq = args[i].indexOf('=');
      if (eq <= 0) {
        System.err.println("not a KEY=VALUE setting: " + args[i]);
        System.exit(2);
      }
      settings.put(args[i].substring(0, eq), args[i].substring(eq + 1));
    }
    TRADEContainer.Builder builder = TRADEContainer.builder();
    settings.forEach(builder::property);

    try (TRADEContainer container = builder.build()) {
      // The container is networked as soon as it is built, so other containers' services may
      // have joined already: "now or when joined" reports those too, each exactly once.
      Watcher watcher = new Watcher();
      TRADEServiceConstraints whereAmI = new TRADEServiceConstraints().name("whereAmI").argTypes();
      container.requestNotification(watcher, "left", whereAmI, null, "left");
      container.registerNotificationNowOrWhenJoined(watcher, whereAmI, "joined");
      container.registerAllServices(new Place(name), "host-" + name, "multihost");
      container.registerAllServices(new Effector(name), "host-" + name, "effectors");
      say("READY " + name + " id=" + container.getId() + " pid=" + ProcessHandle.current().pid()
          + " listening=" + container.getServerAddresses());

      BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
      String line;
      while ((line = in.readLine()) != null) {
        String[] words = line.trim().split("\\s+");
        if (words[0].isEmpty()) {
          continue;
        }
        if (words[0].equals("quit")) {
          break;
        } else if (words[0].equals("call") && (words.length == 2 || words.length == 3)) {
          // On a thread of its own, so that commands go on while a call is in flight.
          long delay = words.length == 3 ? Long.parseLong(words[2]) : -1;
          background(() -> call(container, words[1], delay), "call " + words[1]);
        } else if (words[0].equals("bulk") && words.length == 4) {
          int calls = Integer.parseInt(words[2]);
          int kib = Integer.parseInt(words[3]);
          background(() -> bulk(container, words[1], calls, kib), "bulk " + words[1]);
        } else if (words[0].equals("lock") && words.length == 3) {
          long wait = Long.parseLong(words[2]);
          background(() -> lock(container, words[1].split(","), wait), "lock");
        } else if (words[0].equals("under") && words.length == 2) {
          background(() -> under(container, name, words[1]), "under " + words[1]);
        } else if (words[0].equals("release") && words.length == 1) {
          background(HostNode::release, "release");
        } else if (words[0].equals("locks") && words.length == 1) {
          background(() -> locks(container), "locks");
        } else if (words[0].equals("admin") && (words.length == 4 || words.length == 5)) {
          background(() -> admin(container, words), "admin " + words[3]);
        } else if (words[0].equals("neighbours")) {
          say("NEIGHBOURS " + String.join(",", container.getNeighbours()));
        } else {
          say("UNKNOWN-COMMAND " + line.trim());
        }
      }
    }
    say("BYE");
  }

  private static void background(Runnable task, String what) {
    Thread t = new Thread(task, what);
    t.setDaemon(true);
    t.start();
  }

  private static TRADEServiceInfo effector(TRADEContainer container, String group)
      throws TRADEException {
    return container.getAvailableService(new TRADEServiceConstraints().inGroups(group)
        .name("actuate").argTypes(String.class)).withTimeout(CALL_TIMEOUT);
  }

  /** Locks actuate(String) of every group at once, waiting up to {@code waitMillis}. */
  private static void lock(TRADEContainer container, String[] groups, long waitMillis) {
    try {
      List<TRADEServiceInfo> services = new ArrayList<>();
      for (String g : groups) {
        services.add(effector(container, g));
      }
      TRADELock taken = container.lock(services, Duration.ofMillis(waitMillis));
      lock = taken;
      Map<String, Long> tokens = new TreeMap<>();
      for (TRADELockInfo i : container.getLocks()) {
        if (i.isHolding() && i.getLockId().equals(taken.getId())) {
          tokens.put(i.getService().getContainerName(), i.getFencingToken());
        }
      }
      List<String> pairs = new ArrayList<>();
      tokens.forEach((c, t) -> pairs.add(c + "=" + t));
      say("LOCKED " + taken.getId() + " " + String.join(",", pairs));
    } catch (TRADEException e) {
      say("LOCK-FAILED " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  /** Calls actuate(name) in {@code group} under the lock taken last (none: an ordinary call). */
  private static void under(TRADEContainer container, String name, String group) {
    TRADELock held = lock;
    UUID id = held == null ? null : held.getId();
    try {
      String answer = effector(container, group).call(id, String.class, name);
      say("UNDER-LOCK " + group + " -> " + answer);
    } catch (TRADEException e) {
      say("UNDER-LOCK-FAILED " + group + " " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  private static void release() {
    TRADELock held = lock;
    if (held == null) {
      say("RELEASE-FAILED no lock taken");
      return;
    }
    try {
      held.release();
      lock = null;
      say("RELEASED " + held.getId());
    } catch (TRADEException e) {
      say("RELEASE-FAILED " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  /** Every lease of every container: service@container=holder's container:lock:token. */
  private static void locks(TRADEContainer container) {
    try {
      List<String> rows = new ArrayList<>();
      for (TRADELockInfo i : container.getLocks()) {
        if (i.isHolding()) {
          rows.add(i.getService().serviceString + "@" + i.getService().getContainerName() + "="
              + i.getContainerName() + ":" + i.getLockId() + ":" + i.getFencingToken());
        }
      }
      Collections.sort(rows);
      say("LOCKS " + String.join(" ", rows));
    } catch (TRADEException e) {
      say("LOCKS-FAILED " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  /** Finds whereAmI() (or, with a delay, whereAmIAfter(long)) in {@code group} and calls it. */
  private static void call(TRADEContainer container, String group, long delay) {
    long start = System.nanoTime();
    try {
      TRADEServiceConstraints c = new TRADEServiceConstraints().inGroups(group);
      if (delay < 0) {
        c.name("whereAmI").argTypes();
      } else {
        c.name("whereAmIAfter").argTypes(long.class);
      }
      TRADEServiceInfo info = container.getAvailableService(c);
      Duration timeout = CALL_TIMEOUT.plusMillis(Math.max(0, delay));
      String answer = delay < 0 ? info.withTimeout(timeout).call(String.class)
          : info.withTimeout(timeout).call(String.class, delay);
      say("CALLED " + group + " -> " + answer + " in "
          + Duration.ofNanos(System.nanoTime() - start).toMillis() + " ms");
    } catch (TRADEException e) {
      say("CALL-FAILED " + group + " " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  /**
   * {@code admin <credentials> <container> <operation> [<argument>]}: calls the middleware service
   * {@code operation} of the container named {@code container}, as {@code credentials} ({@code -}:
   * anonymously, as this container's own principal, which it has not).
   */
  private static void admin(TRADEContainer container, String[] words) {
    String credentials = words[1];
    String target = words[2];
    String operation = words[3];
    String what = operation + "@" + target;
    try {
      TRADEServiceInfo service = null;
      for (TRADEServiceInfo s : container.getAvailableServices(new TRADEServiceConstraints()
          .inGroups("trade.system").name(operation))) {
        if (s.getContainerName().equals(target)) {
          service = s;
        }
      }
      if (service == null) {
        say("ADMIN-FAILED " + what + " no " + operation + " of " + target + " is known here");
        return;
      }
      Object[] args = words.length == 4 ? new Object[0]
          : operation.equals("startProvider") ? new Object[] {words[4], List.of("lamp")}
          : new Object[] {words[4]};
      Object result = credentials.equals("-") ? service.call(Object.class, args)
          : container.callAs(credentials, service, Object.class, args);
      say("ADMIN " + what + " -> " + result);
    } catch (TRADEException e) {
      say("ADMIN-FAILED " + what + " " + e.getClass().getSimpleName() + ": " + e.getMessage());
    }
  }

  /** Makes {@code calls} calls of {@code length(byte[])} in {@code group} at once, {@code kib} KiB each. */
  private static void bulk(TRADEContainer container, String group, int calls, int kib) {
    long start = System.nanoTime();
    List<CompletableFuture<Integer>> results = new ArrayList<>();
    try {
      TRADEServiceInfo info = container.getAvailableService(
          new TRADEServiceConstraints().inGroups(group).name("length")).withTimeout(BULK_TIMEOUT);
      for (int i = 0; i < calls; i++) {
        CompletableFuture<Integer> result = new CompletableFuture<>();
        results.add(result);
        Thread t = new Thread(() -> {
          try {
            result.complete(info.call(Integer.class, (Object) new byte[kib * 1024]));
          } catch (TRADEException e) {
            result.completeExceptionally(e);
          }
        }, "bulk call " + i);
        t.setDaemon(true);
        t.start();
      }
    } catch (TRADEException e) {
      say("BULK-FAILED " + group + " " + calls + " of " + calls + ": " + e);
      return;
    }
    List<String> failures = new ArrayList<>();
    for (CompletableFuture<Integer> result : results) {
      try {
        if (result.join() != kib * 1024) {
          failures.add("wrong length " + result.join());
        }
      } catch (CompletionException e) {
        failures.add(e.getCause().toString());
      }
    }
    long ms = Duration.ofNanos(System.nanoTime() - start).toMillis();
    say(failures.isEmpty() ? "BULK " + group + " " + calls + " answered in " + ms + " ms"
        : "BULK-FAILED " + group + " " + failures.size() + " of " + calls + ": " + failures.get(0));
  }

  /** This namespace's IPv4 addresses other than loopback: which host answered. */
  static List<String> ipv4Addresses() {
    List<String> result = new ArrayList<>();
    try {
      for (NetworkInterface nif : Collections.list(NetworkInterface.getNetworkInterfaces())) {
        for (InetAddress a : Collections.list(nif.getInetAddresses())) {
          if (a instanceof Inet4Address && !a.isLoopbackAddress()) {
            result.add(a.getHostAddress());
          }
        }
      }
    } catch (SocketException e) {
      result.add("?");
    }
    Collections.sort(result);
    return result;
  }

  private static synchronized void say(String line) {
    System.out.println(line + " t=" + System.currentTimeMillis());
    System.out.flush();
  }
}
