package dev.trade.internal.net.link;

import java.io.IOException;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Makes authenticated links: accepts connections on the listen addresses and connects to peers,
 * running the {@link Handshake} on each socket before anything else is read. Configured peers are
 * retried with exponential backoff and reconnected after a loss.
 *
 * <p>This class is safe for concurrent use.
 */
public final class Connector {
  private static final Logger LOG = System.getLogger("dev.trade.net");
  private static final long MIN_BACKOFF_MS = 50;
  private static final long MAX_BACKOFF_MS = 2_000;
  /**
   * The most inbound handshakes in progress at once. Each holds a thread until the peer finishes or
   * TIMEOUT_CLIENT_SOCKET passes, and before authentication anyone may connect: without a bound, a
   * flood of connections that never send their HELLO would grow threads without limit.
   */
  public static final int MAX_HANDSHAKES = 64;

  /** Receives every link whose handshake succeeded. */
  public interface Sink {
    void linked(Socket socket, Handshake.Peer peer, boolean initiatedHere);

    /** Whether a live link to the container last reached at this address exists. */
    boolean isLinked(InetSocketAddress address);

    /**
     * A handshake has begun with a peer whose HELLO says it is container {@code peer} (not proved
     * until the handshake ends); this side's AUTH is sent after this returns.
     */
    void handshakeBegun(UUID peer);

    /** A handshake {@link #handshakeBegun} told of ended, linked (after {@link #linked}) or not. */
    void handshakeEnded(UUID peer);
  }

  private final Handshake handshake;
  private final int connectTimeoutMs;
  private final ExecutorService workers;
  private final ThreadPoolExecutor handshakes;
  private final ScheduledExecutorService timer;
  private final Sink sink;
  private final List<ServerSocket> servers = new CopyOnWriteArrayList<>();
  private final Map<InetSocketAddress, Long> backoff = new ConcurrentHashMap<>();
  private final RepeatedFailures<InetSocketAddress> failures =
      new RepeatedFailures<>(TimeUnit.MINUTES.toNanos(1));
  /** Per kept address, the number of its one live retry chain; older chains end at their next step. */
  private final Map<InetSocketAddress, AtomicLong> chains = new ConcurrentHashMap<>();
  private volatile boolean closed;

  /**
   * @param name the container's name, for thread names
   * @param workers runs outbound connects
   */
  public Connector(String name, Handshake handshake, int connectTimeoutMs, ExecutorService workers,
      ScheduledExecutorService timer, Sink sink) {
    this.handshake = handshake;
    this.connectTimeoutMs = connectTimeoutMs;
    this.workers = workers;
    this.timer = timer;
    this.sink = sink;
    AtomicInteger n = new AtomicInteger();
    this.handshakes = new ThreadPoolExecutor(0, MAX_HANDSHAKES, 1, TimeUnit.SECONDS,
        new SynchronousQueue<>(), r -> {
          Thread t = new Thread(r, "trade-handshake-" + name + "-" + n.incrementAndGet());
          t.setDaemon(true);
          return t;
        });
  }

  /** Binds a listening socket (port 0: any free port) and starts accepting; returns its address. */
  public InetSocketAddress listen(InetSocketAddress address) throws IOException {
    ServerSocket server = new ServerSocket();
    server.setReuseAddress(true);
    server.bind(address, 64);
    servers.add(server);
    Thread t = new Thread(() -> acceptLoop(server), "trade-accept-" + server.getLocalPort());
    t.setDaemon(true);
    t.start();
    InetSocketAddress bound = (InetSocketAddress) server.getLocalSocketAddress();
    LOG.log(Level.DEBUG, "listening on {0}", bound);
    return bound;
  }

  /**
   * Stops accepting connections: closes every listening socket (links already made stay).
   *
   * @return the addresses it listened on
   */
  public List<InetSocketAddress> stopListening() {
    List<InetSocketAddress> stopped = new ArrayList<>();
    for (ServerSocket s : servers) {
      stopped.add((InetSocketAddress) s.getLocalSocketAddress());
      servers.remove(s);
      try {
        s.close(); // its accept loop ends on the SocketException
      } catch (IOException ignored) {
        // Closed either way.
      }
    }
    return stopped;
  }

  /** The addresses we listen on, wildcards as they are (see {@link #announceable}). */
  public List<InetSocketAddress> listening() {
    List<InetSocketAddress> result = new ArrayList<>();
    for (ServerSocket s : servers) {
      result.add((InetSocketAddress) s.getLocalSocketAddress());
    }
    return result;
  }

  /**
   * The addresses to announce: those we listen on, a wildcard expanded to the addresses of every
   * up interface (link-local ones left out: their scope cannot travel).
   */
  public List<InetSocketAddress> announceable() {
    List<InetSocketAddress> result = new ArrayList<>();
    for (InetSocketAddress a : listening()) {
      if (!a.getAddress().isAnyLocalAddress()) {
        result.add(a);
        continue;
      }
      try {
        for (NetworkInterface nif : Collections.list(NetworkInterface.getNetworkInterfaces())) {
          if (nif.isUp()) {
            for (InetAddress ip : Collections.list(nif.getInetAddresses())) {
              if (!ip.isLinkLocalAddress() && ip.getClass() == a.getAddress().getClass()) {
                result.add(new InetSocketAddress(ip, a.getPort()));
              }
            }
          }
        }
      } catch (SocketException e) {
        LOG.log(Level.WARNING, "cannot list network interfaces: {0}", e.getMessage());
      }
    }
    return result;
  }

  /** Keeps a link to {@code address}: connects now, retries with backoff, reconnects after loss. */
  public void keepConnected(InetSocketAddress address) {
    chains.putIfAbsent(address, new AtomicLong());
    restart(address);
  }

  /**
   * Connects once to a configured address and never again (KEEPTRYING=false): a failure is
   * reported at WARNING, since nothing will retry it.
   */
  public void dialOnce(InetSocketAddress address) {
    try {
      workers.execute(() -> {
        try {
          connect(address);
        } catch (IOException | Handshake.Failure | RuntimeException e) {
          LOG.log(Level.WARNING, "cannot connect to {0}: {1}; not retrying (KEEPTRYING=false)",
              address, e.getMessage());
        }
      });
    } catch (RejectedExecutionException e) {
      // Closing: nothing to connect for.
    }
  }

  /** Connects once to an address heard from discovery (no retries: it announces again). */
  public void connectOnce(InetSocketAddress address) {
    try {
      workers.execute(() -> {
        try {
          connect(address);
        } catch (IOException | Handshake.Failure e) {
          LOG.log(Level.DEBUG, "cannot connect to announced {0}: {1}", address, e.getMessage());
        }
      });
    } catch (RejectedExecutionException e) {
      // Closing: nothing to connect for.
    }
  }

  /** Retries every kept address now (a link was lost). */
  public void retryNow() {
    for (InetSocketAddress a : chains.keySet()) {
      restart(a);
    }
  }

  /**
   * Starts a new retry chain for {@code address} at once, ending the current one: each chain
   * reschedules itself forever, so without this every lost link would add one more.
   */
  private void restart(InetSocketAddress address) {
    long chain = chains.get(address).incrementAndGet();
    backoff.put(address, MIN_BACKOFF_MS);
    schedule(address, chain, 0);
  }

  private void attempt(InetSocketAddress address, long chain) {
    if (closed || chains.get(address).get() != chain) {
      return;
    }
    long delay = backoff.getOrDefault(address, MIN_BACKOFF_MS);
    if (sink.isLinked(address)) {
      // Linked already (maybe the peer connected to us): look again later, cheaply.
      schedule(address, chain, MAX_BACKOFF_MS);
      return;
    }
    workers.execute(() -> {
      try {
        connect(address);
        failures.succeeded(address);
        backoff.put(address, MIN_BACKOFF_MS);
        schedule(address, chain, MAX_BACKOFF_MS);
      } catch (IOException | Handshake.Failure | RuntimeException e) {
        if (closed) {
          return; // closing ended the attempt: nothing failed, and nothing will retry
        }
        logFailure(address, e.getMessage(), delay, System.nanoTime());
        backoff.put(address, Math.min(MAX_BACKOFF_MS, delay * 2));
        schedule(address, chain, delay);
      }
    });
  }

  /**
   * The first quick retries are DEBUG (a peer that is starting answers within them); once the
   * backoff is at its longest the failure is reported at INFO, and then summarised at most once
   * a minute however long the peer stays away.
   */
  private void logFailure(InetSocketAddress address, String why, long delayMs, long now) {
    RepeatedFailures.Report r = delayMs >= MAX_BACKOFF_MS ? failures.failed(address, why, now) : null;
    if (r == null) {
      LOG.log(Level.DEBUG, "cannot connect to {0}: {1}; retrying in {2} ms", address, why, delayMs);
    } else if (r.first()) {
      LOG.log(Level.INFO, "cannot connect to {0}: {1}; retrying every {2} ms", address, why, delayMs);
    } else {
      LOG.log(Level.INFO, "cannot connect to {0}: {1}; failed {2} more times in the last {3} s,"
          + " still retrying every {4} ms", address, why, r.repeats(),
          TimeUnit.NANOSECONDS.toSeconds(r.sinceNanos()), delayMs);
    }
  }

  private void schedule(InetSocketAddress address, long chain, long delayMs) {
    try {
      timer.schedule(() -> attempt(address, chain), delayMs, TimeUnit.MILLISECONDS);
    } catch (RejectedExecutionException e) {
      // Closing: nothing to connect for.
    }
  }

  private void connect(InetSocketAddress address) throws IOException, Handshake.Failure {
    Socket socket = new Socket();
    try {
      socket.connect(address, connectTimeoutMs);
      handshakeAndHandOver(socket, true);
    } catch (IOException | Handshake.Failure | RuntimeException e) {
      socket.close();
      throw e;
    }
  }

  private void acceptLoop(ServerSocket server) {
    while (!closed) {
      Socket socket;
      try {
        socket = server.accept();
      } catch (SocketException e) {
        break; // closed
      } catch (IOException e) {
        LOG.log(Level.WARNING, "accept failed on {0}: {1}", server.getLocalSocketAddress(), e);
        continue;
      }
      try {
        handshakes.execute(() -> {
          try {
            handshakeAndHandOver(socket, false);
          } catch (IOException | Handshake.Failure | RuntimeException e) {
            refused(socket, e.getMessage());
          }
        });
      } catch (RejectedExecutionException e) {
        refused(socket, closed ? "closing" : MAX_HANDSHAKES + " handshakes in progress already");
      }
    }
  }

  private static void refused(Socket socket, String reason) {
    LOG.log(Level.WARNING, "refused connection from {0}: {1}", socket.getRemoteSocketAddress(), reason);
    try {
      socket.close();
    } catch (IOException ignored) {
      // Already failing; nothing more to tell.
    }
  }

  private void handshakeAndHandOver(Socket socket, boolean initiatedHere)
      throws IOException, Handshake.Failure {
    socket.setTcpNoDelay(true);
    socket.setKeepAlive(true);
    // Closing the socket at the deadline bounds the whole handshake, also against a peer that
    // sends a byte now and then. No SO_TIMEOUT besides: a timed read switches the JDK's socket to
    // non-blocking mode for good, and the link's thread would then make three system calls (a read
    // that finds nothing, poll, the read) each time it runs dry instead of one blocking read.
    AtomicBoolean settled = new AtomicBoolean(); // by the deadline or by the end of the handshake
    ScheduledFuture<?> deadline;
    try {
      deadline = timer.schedule(() -> {
        if (settled.compareAndSet(false, true)) {
          try {
            socket.close();
          } catch (IOException ignored) {
            // The reading thread fails either way.
          }
        }
      }, connectTimeoutMs, TimeUnit.MILLISECONDS);
    } catch (RejectedExecutionException e) {
      throw new IOException("container closing");
    }
    UUID[] heard = new UUID[1];
    try {
      handOver(socket, initiatedHere, settled, deadline, heard);
    } finally {
      if (heard[0] != null) {
        sink.handshakeEnded(heard[0]);
      }
    }
  }

  private void handOver(Socket socket, boolean initiatedHere, AtomicBoolean settled,
      ScheduledFuture<?> deadline, UUID[] heard) throws IOException, Handshake.Failure {
    Handshake.Peer peer;
    try {
      peer = handshake.run(socket.getInputStream(), socket.getOutputStream(), initiatedHere, id -> {
        heard[0] = id;
        sink.handshakeBegun(id);
      });
    } catch (Handshake.Failure e) {
      LOG.log(Level.WARNING, "handshake with {0} failed: {1}", socket.getRemoteSocketAddress(),
          e.getMessage());
      throw e;
    } catch (IOException e) {
      // Failed because the deadline closed the socket, or failed on its own first.
      throw settled.compareAndSet(false, true) ? e : tooSlow();
    } finally {
      deadline.cancel(false);
    }
    if (!settled.compareAndSet(false, true)) {
      throw tooSlow(); // the deadline closed the socket just now
    }
    sink.linked(socket, peer, initiatedHere);
  }

  private IOException tooSlow() {
    return new IOException("handshake not finished within TIMEOUT_CLIENT_SOCKET=" + connectTimeoutMs
        + " ms");
  }

  /** Waits up to {@code nanos} for the handshakes that {@link #close()} interrupted to end. */
  public void awaitClosed(long nanos) throws InterruptedException {
    handshakes.awaitTermination(nanos, TimeUnit.NANOSECONDS);
  }

  public void close() {
    closed = true;
    handshakes.shutdownNow();
    for (ServerSocket s : servers) {
      try {
        s.close();
      } catch (IOException ignored) {
        // Best effort at shutdown.
      }
    }
  }
}
