package dev.trade.internal.hooks;

import dev.trade.internal.call.Invocation;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;

/**
 * Counts the calls of each service of this container and their durations, as an observer of the
 * host chain: each event is a map lookup and an increment, and nothing here throws. Safe for
 * concurrent use.
 */
final class CallStats implements CallObserver {
  private static final class Stat {
    final ServiceDescriptor service;
    final LongAdder calls = new LongAdder();
    final LongAdder failures = new LongAdder();
    final LatencyHistogram latency = new LatencyHistogram();

    Stat(ServiceDescriptor service) {
      this.service = service;
    }
  }

  private final Map<Long, Stat> byService = new ConcurrentHashMap<>();

  @Override
  public long start(Invocation call) {
    return System.nanoTime();
  }

  @Override
  public void end(Invocation call, long started, Throwable failure) {
    long took = System.nanoTime() - started;
    ServiceDescriptor d = call.service();
    Stat s = byService.get(d.serviceId());
    if (s == null) {
      s = byService.computeIfAbsent(d.serviceId(), k -> new Stat(d));
    }
    s.calls.increment();
    if (failure != null) {
      s.failures.increment();
    }
    s.latency.record(took);
  }

  /**
   * One map per service called since counting began, by signature: {@code service},
   * {@code container} (its name), {@code calls}, {@code failures}, {@code p50Micros} and
   * {@code p99Micros} (doubles, within 12.5 %).
   */
  List<Map<String, Object>> snapshot() {
    List<Map<String, Object>> result = new ArrayList<>();
    for (Stat s : byService.values()) {
      Map<String, Object> m = new LinkedHashMap<>();
      m.put("service", s.service.signature());
      m.put("container", s.service.containerName());
      m.put("calls", s.calls.sum());
      m.put("failures", s.failures.sum());
      m.put("p50Micros", s.latency.percentile(0.50) / 1000.0);
      m.put("p99Micros", s.latency.percentile(0.99) / 1000.0);
      result.add(m);
    }
    result.sort((a, b) -> ((String) a.get("service")).compareTo((String) b.get("service")));
    return result;
  }
}
