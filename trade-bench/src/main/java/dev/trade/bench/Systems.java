package dev.trade.bench;

import java.util.List;

/**
 * The systems under test, by name, in the order the report lists them. {@code trade-alt} is TRADE
 * again, for A/B runs of a change in the same run: its server JVM, and its client in the harness's
 * JVM ({@link AltTrade}), run on the class path given by {@code -Dbench.altClasspath=...} (another
 * build of trade-core).
 */
final class Systems {
  static final List<String> ALL = List.of("raw-tcp", "rmi", "grpc", "jgroups", "trade");

  private Systems() {}

  static Rpc.Server serve(String system) throws Exception {
    switch (system) {
      case "raw-tcp": return RawTcp.serve();
      case "rmi": return Rmi.serve();
      case "grpc": return Grpc.serve();
      case "jgroups": return JGroupsRpc.serve();
      case "trade", "trade-alt": return TradeRpc.serve();
      default: throw new IllegalArgumentException("unknown system " + system);
    }
  }

  static Rpc connect(String system, String address) throws Exception {
    switch (system) {
      case "raw-tcp": return RawTcp.connect(address);
      case "rmi": return Rmi.connect(address);
      case "grpc": return Grpc.connect(address);
      case "jgroups": return JGroupsRpc.connect(address);
      case "trade": return TradeRpc.connect(address);
      case "trade-alt": return AltTrade.connect(address);
      default: throw new IllegalArgumentException("unknown system " + system);
    }
  }
}
