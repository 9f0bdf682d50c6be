package dev.trade.internal.hooks;

import dev.trade.TRADEAccess;
import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceUnavailableException;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.registry.Registry;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.SystemGroup;
import java.lang.System.Logger;
import java.lang.System.Logger.Level;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * The system service of hooks, one per container in the reserved group: any container (and any
 * client that can call services) adds, removes and lists the hooks on this container's services
 * through it. Its methods, their parameter and return types, are specified in docs/hooks.md so that
 * other implementations can provide and call them.
 *
 * <p>Public only because services must be; the module does not export it. Safe for concurrent use.
 *
 * <p>Open to every caller ({@link TRADEAccess#ANYONE}), although it is in the reserved group, as the
 * notification and lock services are: containers use it on their users' behalf, without
 * credentials. An access file can restrict it by service name (docs/security.md).
 */
@TRADEAccess(TRADEAccess.ANYONE)
public final class HookService {
  private static final Logger LOG = System.getLogger("dev.trade.hooks");
  /** How long a request waits for its wrapper to be known here; see {@link HookTable#awaitKnown}. */
  static final long KNOWN_WAIT_MS = 5000;
  private static final String ARRAY = "java.lang.Object[]";
  private static final String THROWABLE = "java.lang.Throwable";
  private static final String MAP = "java.util.Map";

  private final HookTable table;
  private final Registry registry;
  private final InfoBinding infos;
  private final boolean systemTargets;

  /** @param systemTargets whether services of the reserved group may be hooked (HOOKSYSTEMSERVICES) */
  HookService(HookTable table, Registry registry, InfoBinding infos, boolean systemTargets) {
    this.table = Objects.requireNonNull(table, "table == null");
    this.registry = Objects.requireNonNull(registry, "registry == null");
    this.infos = Objects.requireNonNull(infos, "infos == null");
    this.systemTargets = systemTargets;
  }

  /**
   * Adds a hook on a service of this container; adding one of the same kind, wrapper and target
   * again returns the first one's id.
   *
   * @param kind before, after or after-async
   * @param wrapper the service called with the call's array: one {@code Object[]} parameter, or
   *     for after hooks {@code (Object[], Throwable)} to learn the target's failure
   * @param target a service of this container
   * @param set the set hook this belongs to, or "" (removeHooks removes a set)
   * @param requester who asks, for the list and the log (a container's name)
   * @return the hook's id: this container's id, ':', a number
   * @throws TRADEException a bad request ({@code TRADEBadArgumentsException}: an unknown kind, a
   *     wrapper of the wrong shape, a target of another container or of the reserved group when
   *     that is not allowed) or a wrapper not known here ({@code TRADEServiceUnavailableException});
   *     nothing added
   */
  @TRADEService
  public String addHook(String kind, TRADEServiceInfo wrapper, TRADEServiceInfo target, String set,
      String requester) throws TRADEException {
    Kind k = Kind.parse(kind);
    ServiceDescriptor w = describe(wrapper, "wrapper");
    ServiceDescriptor t = describe(target, "target");
    checkTarget(t);
    int parameters = checkWrapper(k, w);
    try {
      if (!table.awaitKnown(registry, w, KNOWN_WAIT_MS)) {
        throw unknown(w);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      throw new TRADEException("Interrupted while waiting for wrapper " + Hook.where(w)
          + " to be known");
    }
    Hook[] added = new Hook[1];
    // Under the registry's lock: a wrapper or target that leaves meanwhile cannot leave a hook.
    registry.runLocked(() -> {
      if (registry.entry(w) != null && registry.local(t.serviceId()) != null) {
        added[0] = table.add(k, w, t, parameters, set == null ? "" : set,
            requester == null ? "" : requester);
      }
    });
    if (added[0] == null) {
      throw registry.entry(w) == null ? unknown(w) : new TRADEServiceUnavailableException(
          "Service not available any longer: " + Hook.where(t) + " (it was deregistered)");
    }
    LOG.log(Level.DEBUG, "{0} added by {1}", added[0], requester);
    return added[0].id;
  }

  /**
   * Removes the hook of that kind, wrapper and target.
   *
   * @return whether there was one
   * @throws TRADEException {@code TRADEBadArgumentsException} for an unknown kind
   */
  @TRADEService
  public boolean removeHook(String kind, TRADEServiceInfo wrapper, TRADEServiceInfo target)
      throws TRADEException {
    return table.remove(Kind.parse(kind), describe(wrapper, "wrapper"), describe(target, "target"));
  }

  /**
   * Removes every hook of a set hook in this container.
   *
   * @return how many
   */
  @TRADEService
  public int removeHooks(String set) {
    return set == null ? 0 : table.removeSet(set);
  }

  /** The hooks of this container, in order of addition: one map each, keys as in docs/hooks.md. */
  @TRADEService
  public List<Map<String, Object>> listHooks() {
    List<Map<String, Object>> result = new ArrayList<>();
    for (Hook h : table.all()) {
      result.add(h.describe());
    }
    return result;
  }

  private ServiceDescriptor describe(TRADEServiceInfo info, String what)
      throws TRADEBadArgumentsException {
    if (info == null) {
      throw new TRADEBadArgumentsException("A hook needs a " + what + " service, not null");
    }
    return infos.describe(info);
  }

  private void checkTarget(ServiceDescriptor t) throws TRADEBadArgumentsException {
    if (!t.containerId().equals(registry.containerId())) {
      throw new TRADEBadArgumentsException("Target " + Hook.where(t) + " is provided by container "
          + t.containerId() + ", not by " + registry.containerId() + ": a hook is added at the"
          + " container that provides its target, through that container's addHook");
    }
    if (!systemTargets && t.groups().contains(SystemGroup.NAME)) {
      throw new TRADEBadArgumentsException("Target " + Hook.where(t) + " is in group "
          + SystemGroup.NAME + ", whose services this container does not let hooks wrap; set"
          + " HOOKSYSTEMSERVICES=true in its configuration to allow it");
    }
  }

  /** Returns how many of the parameters a hook passes the wrapper takes (see {@link Hook}). */
  private static int checkWrapper(Kind k, ServiceDescriptor w) throws TRADEBadArgumentsException {
    List<String> p = w.parameterTypeNames();
    if (p.size() == 1 && p.get(0).equals(ARRAY)) {
      return 1;
    }
    if (k.isAfter() && p.size() >= 2 && p.size() <= 3 && p.get(0).equals(ARRAY)
        && p.get(1).equals(THROWABLE) && (p.size() == 2 || p.get(2).equals(MAP))) {
      return p.size();
    }
    throw new TRADEBadArgumentsException("Wrapper " + Hook.where(w) + " cannot take a hook's"
        + " call: it must take one Object[]" + (k.isAfter()
            ? " (or Object[] and Throwable, to learn that the target threw; or those and a Map,"
                + " for the call's details)" : ""));
  }

  private TRADEServiceUnavailableException unknown(ServiceDescriptor w) {
    return new TRADEServiceUnavailableException("Service not available: wrapper " + Hook.where(w)
        + " is not known in container " + registry.containerId() + " (waited " + KNOWN_WAIT_MS
        + " ms for it)");
  }
}
