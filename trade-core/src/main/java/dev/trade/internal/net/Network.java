package dev.trade.internal.net;

import static dev.trade.internal.net.ControlExecutor.daemon;

import dev.trade.TRADEException;
import dev.trade.internal.call.CallContext;
import dev.trade.internal.call.Provider;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.config.PeerAddress;
import dev.trade.internal.config.Settings;
import dev.trade.internal.net.join.Finder;
import dev.trade.internal.net.link.Connector;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Heartbeat;
import dev.trade.internal.net.link.Link;
import dev.trade.internal.net.link.LinkReferee;
import dev.trade.internal.net.link.ReadWatch;
import dev.trade.internal.net.mesh.Replication;
import dev.trade.internal.net.remote.RemoteCalls;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.time.Scheduler;
import java.io.IOException;
import java.lang.System.Logger.Level;
import java.lang.System.Logger;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

/**
 * A container's networking: links to neighbours, replication of service tables and link states,
 * routing, remote calls and failure detection.
 *
 * <p>All state changes (links up and down, tables, link states) run on one control thread, in
 * order; calls and replies take the fast path through the link reader threads and an executor.
 * This class is safe for concurrent use.
 */
public final class Network implements AutoCloseable {
  private static final Logger LOG = System.getLogger("dev.trade.net");

  private final Settings settings;
  private final UUID self;
  private final String name;
  private final Registry registry;
  private final ExecutorService control;
  /** The container's; its timer is shared, so this cancels its own tasks and never shuts it. */
  private final Scheduler scheduler;
  private final ScheduledExecutorService timer;
  private final ExecutorService workers;
  private final Connector connector;
  private final RemoteCalls calls;
  private final Replication replication;
  private final ReadWatch readWatch;
  private final FrameDispatcher dispatch;
  private final Finder discovery;
  private final LinkReferee swaps;
  private final Heartbeat heartbeat;
  private final Map<UUID, Link> links = new ConcurrentHashMap<>();
  /**
   * Every link whose reader runs, registered in {@link #links} or not yet: heartbeats and the
   * read watch look at these, so that a link is read and kept alive from its handshake on, however
   * long the control thread takes to get to it.
   */
  private final Set<Link> live = ConcurrentHashMap.newKeySet();
  /** The peer at each address this container dialled, while that peer is linked. */
  private final Map<InetSocketAddress, UUID> dialled = new ConcurrentHashMap<>();
  /** How long close() lets the goodbyes, and what was queued before them, be written. */
  static final long CLOSE_GRACE_MS = 2000;
  private volatile boolean closed;

  /**
   * @param codec the codec for call values (service infos bind to this container)
   * @param tableCodec a codec whose service-info binding is the descriptor itself
   * @param scheduler the container's clock and timer; its owner closes it after this
   */
  public Network(Settings settings, UUID self, String name, String host, Registry registry,
      Codec codec, Codec tableCodec, Provider provider, Scheduler scheduler) {
    this.settings = settings;
    this.self = self;
    this.name = name;
    this.registry = registry;
    this.scheduler = scheduler;
    this.timer = scheduler.timer();
    this.workers = Executors.newCachedThreadPool(daemon("trade-worker-" + name));
    this.readWatch = new ReadWatch(live, workers, name);
    this.calls = new RemoteCalls(self, codec, this::nextHop, provider, scheduler,
        settings.maxFrameSize());
    this.replication = new Replication(self, registry, tableCodec, links,
        settings.failureTimeout().plus(settings.heartbeatInterval()).toNanos(),
        this::onControlAfter, this::unreachable);
    // The frames of a burst of state changes leave together (one system call per link).
    this.control = new ControlExecutor(daemon("trade-control-" + name), replication::flushQueued);
    this.heartbeat = new Heartbeat(live, settings.heartbeatInterval(), settings.failureTimeout(),
        scheduler, workers);
    this.dispatch = new FrameDispatcher(calls, replication, this, heartbeat,
        FrameDispatcher.backlogLimit(settings.maxFrameSize()));
    if (settings.defaultCredentialsBeyondThisHost()) {
      LOG.log(Level.WARNING, "{0}: CREDENTIALS has its published default value, and this container"
          + " reaches beyond this host: anyone who can reach it can join the system. Give every"
          + " container of the system the same CREDENTIALS of its own (docs/security.md).", name);
    }
    Handshake handshake = new Handshake(new Handshake.Identity(settings.tradeSysId(), self, name,
        host, List.of(), settings.useEncryption(), true, settings.maxFrameSize()),
        settings.credentials());
    this.swaps = new LinkReferee(settings.clientSocketTimeout().toNanos(),
        settings.failureTimeout().toNanos(), this::onControlAfter);
    this.connector = new Connector(name, handshake, (int) settings.clientSocketTimeout().toMillis(),
        workers, timer, new Connector.Sink() {
          @Override
          public void linked(Socket socket, Handshake.Peer peer, boolean initiatedHere) {
            onLinked(socket, peer, initiatedHere);
          }

          @Override
          public boolean isLinked(InetSocketAddress address) {
            UUID peer = dialled.get(address);
            return peer != null && links.containsKey(peer);
          }

          @Override
          public void handshakeBegun(UUID peer) {
            swaps.begun(peer);
          }

          @Override
          public void handshakeEnded(UUID peer) {
            // On the control thread, after the link's own task if it linked (queued before this).
            onControl(() -> {
              swaps.ended(peer);
              settle(peer);
            });
          }
        });
    this.discovery = new Finder(settings, self, name, connector, this::linkedOrLinking,
        replication::reachable, scheduler, () -> closed);
    registry.addListener(
        (added, removed) -> replication.localChanged(added, removed, this::onControl));
  }

  /**
   * Starts listening (when configured) and connecting to the configured peers.
   *
   * @throws IOException if a listen address cannot be bound (the message names it)
   */
  public void start() throws IOException {
    if (settings.startAcceptingConnections() || settings.startBroadcast()) {
      discovery.listen();
    }
    for (PeerAddress a : settings.connectContainers()) {
      InetSocketAddress address = new InetSocketAddress(a.host(), a.port());
      if (settings.keepTrying()) {
        connector.keepConnected(address);
      } else {
        connector.dialOnce(address);
      }
    }
    heartbeat.start();
    if (settings.startDiscovery() || settings.startBroadcast()) {
      discovery.start(settings.startBroadcast(), settings.startDiscovery());
    }
  }

  /** Announcing, discovery and listening, and their switches. */
  public Finder discovery() {
    return discovery;
  }

  /**
   * A container left or died (routing lost it; on the control thread): the calls waiting on it fail
   * at once, and discovery stops counting it.
   */
  private void unreachable(UUID container) {
    calls.failTo(container, "container " + container + " left or is not reachable any more");
    discovery.unreachable(container);
  }

  /** The addresses this container accepts connections on. */
  public List<InetSocketAddress> listenAddresses() {
    return connector.listening();
  }

  /**
   * The addresses this container would announce now: those it listens on, a wildcard expanded to
   * the addresses of the interfaces that are up now.
   */
  public List<InetSocketAddress> announceable() {
    return connector.announceable();
  }

  /** Ids of the containers this one has a direct link to. */
  public List<String> neighbours() {
    return links.keySet().stream().map(UUID::toString).toList();
  }

  /**
   * The smoothed round-trip time of each direct link whose peer has echoed a heartbeat probe, in
   * nanoseconds, by the peer's id; links not measured yet are left out.
   */
  public Map<String, Long> roundTrips() {
    Map<String, Long> result = new TreeMap<>();
    for (Link l : links.values()) {
      long rtt = l.roundTripNanos();
      if (rtt >= 0) {
        result.put(l.peerKey, rtt);
      }
    }
    return result;
  }

  /**
   * Whether discovery counts {@code peer} as linked: a link, or a handshake under way (registered
   * once a control thread seconds behind gets to it; a dial meanwhile made a duplicate link).
   */
  boolean linkedOrLinking(UUID peer) {
    return links.containsKey(peer) || swaps.handshaking(peer);
  }

  int dialledAddresses() { // for tests
    return dialled.size();
  }

  /** Dials {@code address} once (an administrator's connect; discovery dials through its finder). */
  public void connect(InetSocketAddress address) {
    connector.connectOnce(address);
  }

  /**
   * Accepts connections on {@code address} too (port 0: any free port).
   *
   * @return the address bound
   * @throws IOException if it cannot be bound
   */
  public InetSocketAddress listen(InetSocketAddress address) throws IOException {
    return connector.listen(address);
  }

  /** Stops accepting connections; links already made stay. Returns the addresses it closed. */
  public List<InetSocketAddress> stopListening() {
    return connector.stopListening();
  }

  /**
   * Closes the direct link to {@code container}, if there is one (with a goodbye, so it is not
   * taken for a failure); the container stays reachable over other links if there are any.
   *
   * @return whether there was a link
   */
  public boolean disconnect(UUID container) {
    Link link = links.get(container);
    if (link == null) {
      return false;
    }
    link.leave();
    return true;
  }

  /**
   * Calls a remote service; see {@code ServiceCaller}. The reply is decoded in {@code loader},
   * also allowing the classes named in {@code declared} (those the service's signature declares).
   */
  public Object call(ServiceDescriptor d, Object[] args, CallContext context, long deadlineNanos,
      ClassLoader loader, Set<String> declared) throws TRADEException {
    return calls.call(d, args, context, deadlineNanos, loader, declared);
  }

  /** Calls a remote service without waiting; see {@code RemoteCalls#callAsync}. */
  public CompletableFuture<Object> callAsync(ServiceDescriptor d, Object[] args,
      CallContext context, long deadlineNanos, ClassLoader loader, Set<String> declared,
      Executor executor) {
    return calls.callAsync(d, args, context, deadlineNanos, loader, declared, executor);
  }

  private Link nextHop(UUID container) {
    UUID hop = replication.nextHop(container);
    // No route yet to a direct neighbour whose link state is still on its way: calls are served
    // without waiting for the control thread that applies link states, so the first CALL of a new
    // neighbour can overtake its LINKS. The link itself is the way back.
    return links.get(hop == null ? container : hop);
  }

  private void onLinked(Socket socket, Handshake.Peer peer, boolean initiatedHere) {
    Link link;
    try {
      link = new Link(socket, peer, initiatedHere, settings.maxFrameSize());
    } catch (IOException e) {
      LOG.log(Level.WARNING, "link to {0} failed at once: {1}", peer.name(), e.getMessage());
      return;
    }
    boolean accepted = onControl(() -> {
      if (closed) {
        link.leave();
        return;
      }
      if (initiatedHere) { // kept while the peer is linked, whichever of its links stays
        dialled.put((InetSocketAddress) socket.getRemoteSocketAddress(), peer.containerId());
      }
      Link drop = LinkReferee.toClose(links.get(peer.containerId()), link, self);
      if (drop != null) {
        LOG.log(Level.DEBUG, "{0}: closed a duplicate link to {1}", name, peer.name());
      }
      if (drop == link) {
        swaps.retire(link);
        return;
      }
      // Replaced in one step, then retired: a caller looking up its next hop meanwhile finds one of
      // the two links, never none (no link fails its call at once as "not reachable").
      Link replaced = links.put(peer.containerId(), link);
      if (replaced != null) {
        swaps.retire(replaced);
      }
      // DEBUG, as is an orderly close: at INFO, 100 containers in one JVM spent seconds of their
      // control threads queued for the logging handler's lock (docs/configuration.md, Logging).
      LOG.log(Level.DEBUG, "{0}: linked to {1} ({2})", name, peer.name(), socket.getRemoteSocketAddress());
      replication.linkUp(link);
    });
    if (!accepted) {
      link.leave();
      return;
    }
    // Reading starts here, not on the control thread: with 100 containers that thread fell
    // seconds behind the link states and tables it had to apply, and a link that is neither read
    // nor pinged for FAILURETIMEOUT is closed by its peer as silent. Its frames still reach the
    // control thread after the task above, which registers the link.
    live.add(link);
    if (closed) {
      link.leave(); // close() may have gone over the live links already
    }
    link.start(dispatch, readWatch);
    heartbeat.greet(link);
  }

  /**
   * Runs {@code task} on the control thread; false if the container has closed. Then there is no
   * control thread and no state left to update: link readers that end then must not fail for it.
   */
  boolean onControl(Runnable task) {
    try {
      control.execute(() -> guarded(task));
      return true;
    } catch (RejectedExecutionException e) {
      if (!closed) {
        throw e;
      }
      return false;
    }
  }

  /** Runs {@code task} on the control thread after {@code delayNanos}; nothing once closed. */
  /**
   * Runs a control task so that a failure of one never stops the control thread's work: a frame's
   * own task closes its link (see Replication#received); anything that escapes is a fault here,
   * logged with its stack trace, and the next task runs as usual.
   */
  private void guarded(Runnable task) {
    try {
      task.run();
    } catch (RuntimeException | StackOverflowError e) {
      LOG.log(Level.ERROR, name + ": a control task failed; the container goes on", e);
    }
  }

  private void onControlAfter(Runnable task, long delayNanos) {
    if (delayNanos <= 0) {
      onControl(task);
      return;
    }
    try {
      timer.schedule(() -> onControl(task), delayNanos, TimeUnit.NANOSECONDS);
    } catch (RejectedExecutionException closing) {
      // Nothing left to do it for.
    }
  }

  /** A link's reader ended (its reading thread). */
  void linkClosed(Link link, String reason) {
    live.remove(link);
    onControl(() -> {
      replication.linkClosed(link);
      if (!closed && links.get(link.peerId) == link
          && swaps.hold(link, reason, scheduler.nanoTime())) {
        LOG.log(Level.DEBUG, "{0}: link to {1} closed ({2}); a handshake with it is under way,"
            + " the loss waits for it", name, link.peerName, reason);
        onControlAfter(() -> settle(link.peerId), swaps.holdNanos()); // its replacement may come
        return;
      }
      lost(link, reason);
    });
  }

  /** Takes a held loss of the link to {@code peer} now, if it is still held and due (LinkReferee). */
  private void settle(UUID peer) {
    LinkReferee.Held h = swaps.settle(peer, links.get(peer), scheduler.nanoTime());
    if (h != null) {
      lost(h.link(), h.reason());
    }
  }

  private void lost(Link link, String reason) {
    if (links.remove(link.peerId, link)) {
      dialled.values().removeIf(link.peerId::equals);
      boolean orderly = closed || reason.equals(FrameDispatcher.GOODBYE);
      LOG.log(orderly ? Level.DEBUG : Level.INFO, "{0}: link to {1} closed: {2}", name,
          link.peerName, reason);
      calls.failVia(link.peerId, "the connection to " + link.peerName + " was lost ("
          + reason + ")");
      if (!closed) { // closing: no routes to follow, no one to dial again
        replication.linkDown(link);
        connector.retryNow();
      }
    }
  }

  /**
   * Says goodbye to every neighbour, closes all links and stops all threads. Returns once every
   * link is closed, within {@link #CLOSE_GRACE_MS}: a link whose goodbye cannot be written by then
   * (a neighbour that does not read) is closed without it, which also ends a write stalled on it.
   */
  @Override
  public void close() {
    if (closed) {
      return;
    }
    closed = true;
    long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(CLOSE_GRACE_MS);
    discovery.close();
    connector.close();
    heartbeat.stop();
    // Also while this thread is stuck writing a goodbye below.
    ScheduledFuture<?> late = timer.schedule(this::closeLinksNow, CLOSE_GRACE_MS,
        TimeUnit.MILLISECONDS);
    live.forEach(Link::leave);
    calls.failAll("container " + name + " closed");
    readWatch.close();
    control.shutdown();
    workers.shutdownNow();
    try {
      control.awaitTermination(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
      // Connects in flight end with their sockets; waiting keeps their last words inside close().
      workers.awaitTermination(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
      connector.awaitClosed(Math.max(0, deadline - System.nanoTime()));
      CompletableFuture.allOf(live.stream().map(Link::whenClosed).toArray(CompletableFuture[]::new))
          .get(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    } catch (TimeoutException | ExecutionException e) {
      // Closed below.
    }
    closeLinksNow();
    late.cancel(false);
  }

  /** Closes every link still open after its goodbye had its time. */
  private void closeLinksNow() {
    live.forEach(l -> l.close("container closed: the goodbye was not written within "
        + CLOSE_GRACE_MS + " ms"));
  }
}
