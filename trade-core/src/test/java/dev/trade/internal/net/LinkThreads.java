package dev.trade.internal.net;

/** The threads that read links, found by name: each link has one, named after its peer. */
final class LinkThreads {
  private LinkThreads() {}

  /** Live link reader threads towards the container named {@code peer}. */
  static int readers(String peer) {
    int n = 0;
    for (Thread t : Thread.getAllStackTraces().keySet()) {
      if (t.isAlive() && t.getName().equals("trade-link-" + peer)) {
        n++;
      }
    }
    return n;
  }
}
