package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;

/**
 * The far container of the notification benchmark, in a JVM of its own: accepts connections on
 * loopback, provides {@link Source} in group {@code notifybench}, prints {@code READY ip@port} and
 * serves until standard input closes. Its links tolerate long silences (the benchmark stops this
 * process to keep calls outstanding).
 */
public final class NotifyProviderMain {
  private NotifyProviderMain() {}

  /** Values to stream, and a call to keep outstanding. */
  public static final class Source {
    private final byte[] big = new byte[64 * 1024];
    private int n;

    @TRADEService
    public int small() {
      return n++;
    }

    @TRADEService
    public byte[] big() {
      return big;
    }

    @TRADEService
    public int echo(int x) {
      return x;
    }
  }

  public static void main(String[] args) throws Exception {
    try (TRADEContainer c = TRADEContainer.builder().name("notify-provider")
        .property("STARTACCEPTINGCONNECTIONS", "true").property("SERVERIPS", "127.0.0.1@0")
        .property("FAILURETIMEOUT", "120000").build()) {
      c.registerAllServices(new Source(), "notifybench");
      System.out.println("READY " + c.getServerAddresses().get(0));
      System.out.flush();
      while (System.in.read() >= 0) {
        // Serve until the parent closes our input.
      }
    }
    System.exit(0);
  }
}
