package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
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
 * The cost of a call inside one JVM: a direct call, a {@link MethodHandle} held in a field (what a
 * hand-written dispatcher would use; not a static final constant, which the JIT would fold into a
 * direct call), and {@code TRADEServiceInfo.call} in a default container and in a strict one
 * ({@code COPYDATAFORLOCALINVOKES=true}), for {@code small(int) -> boolean} and a 1 KB argument.
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@State(Scope.Benchmark)
public class LocalCallBench {
  /** The service. */
  public static class Arm {
    @TRADEService
    public boolean small(int x) {
      return (x & 1) == 0;
    }

    @TRADEService
    public int consume(byte[] data) {
      return data.length;
    }
  }

  private Arm arm;
  private MethodHandle handle;
  private TRADEContainer plain;
  private TRADEContainer strict;
  private TRADEServiceInfo plainSmall;
  private TRADEServiceInfo strictSmall;
  private TRADEServiceInfo plainConsume;
  private TRADEServiceInfo strictConsume;
  private int x;
  private byte[] kilobyte;

  @Setup(Level.Trial)
  public void setUp() throws Exception {
    arm = new Arm();
    handle = MethodHandles.lookup().findVirtual(Arm.class, "small",
        MethodType.methodType(boolean.class, int.class));
    plain = TRADEContainer.builder().name("plain").build();
    strict = TRADEContainer.builder().name("strict").copyDataForLocalInvokes(true).build();
    plain.registerAllServices(new Arm());
    strict.registerAllServices(new Arm());
    plainSmall = plain.getAvailableService(new TRADEServiceConstraints().name("small"));
    strictSmall = strict.getAvailableService(new TRADEServiceConstraints().name("small"));
    plainConsume = plain.getAvailableService(new TRADEServiceConstraints().name("consume"));
    strictConsume = strict.getAvailableService(new TRADEServiceConstraints().name("consume"));
    kilobyte = new byte[1024];
  }

  @TearDown(Level.Trial)
  public void tearDown() {
    plain.close();
    strict.close();
  }

  @Benchmark
  public boolean direct() {
    return arm.small(++x);
  }

  @Benchmark
  public boolean methodHandle() throws Throwable {
    return (boolean) handle.invokeExact(arm, ++x);
  }

  @Benchmark
  public boolean tradeNonStrict() throws Exception {
    return plainSmall.call(boolean.class, ++x);
  }

  @Benchmark
  public boolean tradeStrict() throws Exception {
    return strictSmall.call(boolean.class, ++x);
  }

  @Benchmark
  public int tradeNonStrict1KB() throws Exception {
    return plainConsume.call(int.class, (Object) kilobyte);
  }

  @Benchmark
  public int tradeStrict1KB() throws Exception {
    return strictConsume.call(int.class, (Object) kilobyte);
  }
}
