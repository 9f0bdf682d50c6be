package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;

/**
 * What a typed proxy adds to a local call: {@code TRADEServiceInfo.call} against the same service
 * called through {@code TRADEContainer.proxy} (goal: within 50 ns of the direct {@code call}).
 * These JMH methods measure wall time; {@link ProxyCpu} ({@code BenchMain proxycpu}) judges the goal
 * by CPU time in interleaved pairs, which a busy machine disturbs far less.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Benchmark)
public class ProxyCallBench {
  /** The service. */
  public static class Arm {
    @TRADEService
    public boolean small(int x) {
      return (x & 1) == 0;
    }
  }

  /** How a caller sees it. */
  public interface ArmApi {
    boolean small(int x) throws TRADEException;
  }

  private TRADEContainer container;
  private TRADEServiceInfo info;
  private ArmApi proxy;
  private int x;

  @Setup(Level.Trial)
  public void setUp() throws Exception {
    container = TRADEContainer.builder().name("proxy-bench").build();
    container.registerAllServices(new Arm());
    info = container.getAvailableService(new TRADEServiceConstraints().name("small"));
    proxy = container.proxy(ArmApi.class);
    proxy.small(0); // found now, not in the first measured call
  }

  @TearDown(Level.Trial)
  public void tearDown() {
    container.close();
  }

  @Benchmark
  public boolean call() throws Exception {
    return info.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean proxy() throws Exception {
    return proxy.small(++x);
  }
}
