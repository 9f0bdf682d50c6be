package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.internal.registry.Callbacks;
import dev.trade.internal.registry.Entry;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.lang.invoke.MethodHandle;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.function.Function;

/**
 * "joined" and "left" notifications, computed from changes of the replicated registry: every
 * container sees the same changes, so no extra messages travel.
 *
 * <p>Events are queued, under the registry's lock, to one delivery thread per container, so each
 * event reaches each matching request exactly once and in the order the changes happened; no
 * network or registry thread ever runs a callback. A callback that throws is logged with its
 * context and the next delivery goes on. This class is safe for concurrent use.
 */
public final class Notifications implements Registry.Listener {
  private static final Logger LOG = System.getLogger("dev.trade.notify");

  /** The notification kinds of this class. */
  public enum Type {
    JOINED, LEFT;

    /**
     * @throws TRADEBadArgumentsException naming the supported types
     */
    public static Type parse(String name) throws TRADEBadArgumentsException {
      if (name != null) {
        for (Type t : values()) {
          if (t.name().toLowerCase(Locale.ROOT).equals(name.toLowerCase(Locale.ROOT))) {
            return t;
          }
        }
      }
      throw new TRADEBadArgumentsException("Unknown notification type '" + name
          + "'; supported: joined, left");
    }
  }

  private record Request(Object listener, Type type, Query query, MethodHandle callback, String name) {}

  private final Registry registry;
  private final Class<?> infoType;
  private final Function<ServiceDescriptor, Object> infos;
  private final List<Request> requests = new CopyOnWriteArrayList<>();
  private final ExecutorService delivery;

  /**
   * @param infoType the class of what {@code infos} makes: the callbacks' parameter type
   * @param infos makes the {@code TRADEServiceInfo} handed to callbacks
   */
  public Notifications(Registry registry, Class<?> infoType,
      Function<ServiceDescriptor, Object> infos, String name) {
    this.registry = registry;
    this.infoType = infoType;
    this.infos = infos;
    this.delivery = Executors.newSingleThreadExecutor(r -> {
      Thread t = new Thread(r, "trade-notify-" + name);
      t.setDaemon(true);
      return t;
    });
    registry.addListener(this);
  }

  /**
   * Calls {@code listener.callback(TRADEServiceInfo)} for every service matching {@code query}
   * that joins (or leaves) from now on.
   *
   * @throws TRADEBadArgumentsException unknown type, or no usable callback (the message says why)
   */
  public void request(Object listener, String type, Query query, String callback)
      throws TRADEBadArgumentsException {
    requests.add(newRequest(listener, Type.parse(type), query, callback));
  }

  /**
   * Calls back now for every service already matching, then for every one that joins: the two are
   * one atomic step, so no service is missed or delivered twice.
   */
  public void requestNowOrWhenJoined(Object listener, Query query, String callback)
      throws TRADEBadArgumentsException {
    Request r = newRequest(listener, Type.JOINED, query, callback);
    registry.runLocked(() -> {
      requests.add(r);
      for (Entry e : registry.find(null, query)) {
        enqueue(r, e.descriptor());
      }
    });
  }

  /**
   * Cancels the listener's requests of {@code type} with equal constraints, or all of that type
   * when {@code query} is null.
   *
   * @return how many requests were cancelled
   */
  public int cancel(Object listener, String type, Query query) throws TRADEBadArgumentsException {
    Type t = Type.parse(type);
    int before = requests.size();
    requests.removeIf(r -> r.listener == listener && r.type == t
        && (query == null || r.query.equals(query)));
    return before - requests.size();
  }

  @Override
  public void changed(List<Entry> added, List<Entry> removed) {
    for (Request r : requests) {
      for (Entry e : r.type == Type.JOINED ? added : removed) {
        if (r.query.matches(e, registry.containerId(), registry.host())) {
          enqueue(r, e.descriptor());
        }
      }
    }
  }

  /** Stops delivering; queued events are dropped. */
  public void close() {
    registry.removeListener(this);
    requests.clear();
    delivery.shutdownNow();
  }

  private Request newRequest(Object listener, Type type, Query query, String callback)
      throws TRADEBadArgumentsException {
    if (listener == null || callback == null) {
      throw new TRADEBadArgumentsException("A notification needs a listener and a callback method name");
    }
    return new Request(listener, type, query, Callbacks.find(listener, callback, infoType),
        listener.getClass().getName() + "." + callback);
  }

  private void enqueue(Request r, ServiceDescriptor d) {
    try {
      delivery.execute(() -> deliver(r, d));
    } catch (RejectedExecutionException closed) {
      // The container is closing: nobody is left to tell.
    }
  }

  private void deliver(Request r, ServiceDescriptor d) {
    if (!requests.contains(r)) {
      return; // cancelled while the event waited
    }
    try {
      Object ignored = (Object) r.callback.invokeExact(r.listener, new Object[] {infos.apply(d)});
    } catch (VirtualMachineError e) {
      throw e;
    } catch (Throwable t) {
      LOG.log(Level.WARNING, "notification callback " + r.name + " threw for '"
          + r.type.name().toLowerCase(Locale.ROOT) + "' of " + d.signature() + " @ "
          + d.containerName() + "; later notifications continue", t);
    }
  }
}
