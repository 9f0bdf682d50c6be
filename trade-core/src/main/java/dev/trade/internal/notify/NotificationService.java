package dev.trade.internal.notify;

import dev.trade.TRADEAccess;
import dev.trade.TRADEException;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import dev.trade.internal.call.CurrentCall;
import dev.trade.internal.call.Invocation;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * The system service of notifications, one per container in the reserved group: every container
 * (and any client that can call services) requests, cancels and lists notifications through it,
 * locally or remotely. Its methods, their parameter and return types, are specified in
 * docs/notifications.md so that other implementations can provide and call them.
 *
 * <p>Open to every caller ({@link TRADEAccess#ANYONE}), although it is in the reserved group: every
 * container requests notifications of others on its users' behalf, without credentials. Only
 * {@link #notificationEnded} asks who calls (the host chain binds its call, {@link CurrentCall}):
 * only the container that ran a notification may say that it ended.
 *
 * <p>Public only because services must be; the module does not export it. Safe for concurrent use.
 */
@TRADEAccess(TRADEAccess.ANYONE)
public final class NotificationService {
  private final Notifications engine;
  private final NotificationClient client;
  private final InfoBinding infos;

  public NotificationService(Notifications engine, NotificationClient client, InfoBinding infos) {
    this.engine = Objects.requireNonNull(engine, "engine == null");
    this.client = Objects.requireNonNull(client, "client == null");
    this.infos = Objects.requireNonNull(infos, "infos == null");
  }

  /**
   * Starts a notification in this container.
   *
   * @param type one of joined, left, once, after, at, every, if, when
   * @param argument the type's argument (docs/notifications.md)
   * @param services {@code services[0]}: the service called or the condition (may be null or empty
   *     for types that take none)
   * @param callback the service called back
   * @param requester who asks, for the list and the log (a container's name)
   * @return the notification's id: this container's id, ':', a number
   * @throws TRADEException a bad request ({@code TRADEBadArgumentsException}) or a callback or
   *     service not known here ({@code TRADEServiceUnavailableException}); nothing started
   */
  @TRADEService
  public String requestNotification(String type, Object argument, List<TRADEServiceInfo> services,
      TRADEServiceInfo callback, String requester) throws TRADEException {
    return engine.request(type, argument, describeAll(services), describe(callback), requester);
  }

  /**
   * Starts a joined notification that also calls back at once for every service matching now.
   *
   * @return {@code id} (String) and {@code matches} (the services matching now, in preference order)
   */
  @TRADEService
  public Map<String, Object> requestNotificationNowOrWhenJoined(Object constraints,
      TRADEServiceInfo callback, String requester) throws TRADEException {
    Map.Entry<String, List<ServiceDescriptor>> r =
        engine.requestNowOrWhenJoined(constraints, describe(callback), requester);
    List<Object> matches = new ArrayList<>();
    for (ServiceDescriptor d : r.getValue()) {
      matches.add(infos.bind(d));
    }
    Map<String, Object> result = new LinkedHashMap<>();
    result.put("id", r.getKey());
    result.put("matches", matches);
    return result;
  }

  /**
   * Cancels a notification of this container.
   *
   * @return whether it was live (false: unknown, or ended already)
   */
  @TRADEService
  public boolean cancelNotification(String id) {
    return engine.cancel(id);
  }

  /**
   * Told by the container that ran notification {@code id}, whose callback is a service of this
   * container, that it ended: this container forgets it if it requested it for a listener.
   *
   * @param id the notification's id
   * @param reason why it ended (for the log; as {@code endReason} in the list of ended ones)
   * @throws TRADENotAuthorizedException the caller is not the container that ran it (whose id, and
   *     ':', {@code id} starts with); nothing is forgotten
   */
  @TRADEService
  public void notificationEnded(String id, String reason) throws TRADEException {
    Objects.requireNonNull(id, "id == null");
    Invocation call = CurrentCall.get();
    String caller = call == null ? null : call.caller().container().toString();
    if (caller == null || !id.startsWith(caller + ":")) {
      int colon = id.indexOf(':');
      throw new TRADENotAuthorizedException("notificationEnded(" + id + "): only the container that"
          + " ran the notification may say it ended, container "
          + (colon < 0 ? "(none: the id has no '<container id>:')" : id.substring(0, colon))
          + "; the caller is " + (caller == null ? "not known (not called through the host chain)"
          : "container " + caller) + "; nothing was forgotten");
    }
    client.ended(id);
  }

  /** The live notifications of this container: one map each, keys as in docs/notifications.md. */
  @TRADEService
  public List<Map<String, Object>> listNotifications() {
    return engine.list();
  }

  /** The last notifications of this container that ended, newest first, each with its endReason. */
  @TRADEService
  public List<Map<String, Object>> endedNotifications() {
    return engine.ended();
  }

  private ServiceDescriptor describe(TRADEServiceInfo info) {
    return info == null ? null : infos.describe(info);
  }

  private List<ServiceDescriptor> describeAll(List<TRADEServiceInfo> services) {
    List<ServiceDescriptor> result = new ArrayList<>();
    if (services != null) {
      for (TRADEServiceInfo s : services) {
        result.add(describe(Objects.requireNonNull(s, "services contains null")));
      }
    }
    return result;
  }
}
