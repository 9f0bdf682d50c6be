package dev.trade.bench;

import java.io.IOException;

/**
 * Runs the server side of one system in this JVM: prints {@code READY <address>} and serves until
 * standard input closes (the benchmark ended or died) or 30 minutes passed, whichever comes first.
 */
public final class ServerMain {
  private ServerMain() {}

  public static void main(String[] args) throws Exception {
    Rpc.Server server = Systems.serve(args[0]);
    System.out.println("READY " + server.address());
    System.out.flush();
    Thread watchdog = new Thread(() -> {
      try {
        Thread.sleep(30 * 60_000L);
      } catch (InterruptedException e) {
        return;
      }
      System.err.println("ServerMain " + args[0] + ": 30 min limit reached, exiting");
      Runtime.getRuntime().halt(3);
    });
    watchdog.setDaemon(true);
    watchdog.start();
    try {
      while (System.in.read() >= 0) {
        // Wait for the end of input.
      }
    } catch (IOException ignored) {
      // Parent gone.
    }
    server.close();
    System.exit(0);
  }
}
