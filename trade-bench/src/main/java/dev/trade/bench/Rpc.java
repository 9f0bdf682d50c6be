package dev.trade.bench;

/**
 * The calling side of one system under test. Every system serves the same two operations on the
 * same payloads: {@code small(int) -> boolean} (the "openGripper" shape) and
 * {@code consume(byte[]) -> int} (an argument of 1 KB or 1 MB, the reply is its length).
 *
 * <p>{@link #forCaller()} gives each calling thread what that system's users would give it: raw TCP
 * gets a socket per thread (the best case for it); RMI, gRPC, JGroups and TRADE share one client,
 * channel, dispatcher or container, which multiplex or pool connections themselves.
 */
public interface Rpc extends AutoCloseable {
  boolean small(int x) throws Exception;

  int consume(byte[] data) throws Exception;

  /** A client for one more calling thread (may be this one). */
  default Rpc forCaller() throws Exception {
    return this;
  }

  @Override
  void close() throws Exception;

  /** The server side: started in its own JVM by {@link ServerMain}. */
  interface Server extends AutoCloseable {
    /** What a client needs to connect, one line of text. */
    String address();

    @Override
    void close() throws Exception;
  }

  /** The implementation both sides call. */
  final class Service {
    private Service() {}

    public static boolean small(int x) {
      return (x & 1) == 0;
    }

    public static int consume(byte[] data) {
      return data.length;
    }
  }
}
