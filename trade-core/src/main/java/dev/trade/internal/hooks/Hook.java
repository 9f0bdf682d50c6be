package dev.trade.internal.hooks;

import dev.trade.internal.call.CallContext;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;

/**
 * One hook installed in this container: its wrapper is called {@link Kind before or after} its
 * target. Immutable but for its counters, which are safe for concurrent use.
 */
final class Hook {
  final String id;
  final Kind kind;
  final ServiceDescriptor wrapper;
  final ServiceDescriptor target;
  /**
   * The wrapper's parameters: 1, the array; 2, also the target's failure ({@code Throwable}); 3,
   * also the call's details ({@code Map}: see docs/hooks.md).
   */
  final int parameters;
  /** The set hook this belongs to ({@code <container id>:set<n>}), or "" for a single hook. */
  final String set;
  final String requester;
  /** The wrapper's key in a hook path ({@link HookPath}). */
  final String key;
  /** The context of the wrapper's call when the target's call has no path: made once. */
  final CallContext solo;
  final LongAdder calls = new LongAdder();
  final LongAdder failures = new LongAdder();
  /** Whether a failure was logged at WARNING already: later ones go to DEBUG, all are counted. */
  final AtomicBoolean warned = new AtomicBoolean();

  Hook(String id, Kind kind, ServiceDescriptor wrapper, ServiceDescriptor target,
      int parameters, String set, String requester) {
    this.id = id;
    this.kind = kind;
    this.wrapper = wrapper;
    this.target = target;
    this.parameters = parameters;
    this.set = set;
    this.requester = requester;
    this.key = HookPath.key(wrapper.containerId(), wrapper.serviceId());
    this.solo = HookPath.inside(null, key);
  }

  boolean same(Kind k, ServiceDescriptor w, ServiceDescriptor t) {
    return kind == k && wrapper.sameService(w) && target.sameService(t);
  }

  /** As docs/hooks.md lists hooks. */
  Map<String, Object> describe() {
    Map<String, Object> m = new LinkedHashMap<>();
    m.put("id", id);
    m.put("kind", kind.label());
    m.put("wrapper", where(wrapper));
    m.put("target", where(target));
    m.put("set", set);
    m.put("requester", requester);
    m.put("calls", calls.sum());
    m.put("failures", failures.sum());
    return m;
  }

  static String where(ServiceDescriptor d) {
    return d.signature() + "@" + d.containerName();
  }

  @Override
  public String toString() {
    return "hook " + id + " (" + kind.label() + " " + where(target) + ": " + where(wrapper) + ")";
  }
}
