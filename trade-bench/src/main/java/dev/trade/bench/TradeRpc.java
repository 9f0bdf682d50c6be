package dev.trade.bench;

import dev.trade.TRADEContainer;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.IOException;

/**
 * TRADE remote calls between two containers in two JVMs: the server container accepts on
 * 127.0.0.1, the client container connects to it, looks the services up once and calls them
 * through their {@link TRADEServiceInfo}s from every calling thread (one link, shared).
 */
final class TradeRpc {
  /** The provider. */
  public static final class Impl {
    @TRADEService
    public boolean small(int x) {
      return Rpc.Service.small(x);
    }

    @TRADEService
    public int consume(byte[] data) {
      return Rpc.Service.consume(data);
    }
  }

  private TradeRpc() {}

  static Rpc.Server serve() throws Exception {
    TRADEContainer c = TRADEContainer.builder().name("bench-server")
        .property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", "127.0.0.1@0")
        .build();
    c.registerAllServices(new Impl());
    return new Rpc.Server() {
      @Override
      public String address() {
        return c.getServerAddresses().get(0);
      }

      @Override
      public void close() {
        c.close();
      }
    };
  }

  static Rpc connect(String address) throws Exception {
    TRADEContainer c = TRADEContainer.builder().name("bench-client")
        .property("CONNECTCONTAINERS", address)
        .build();
    TRADEServiceInfo small = await(c, "small");
    TRADEServiceInfo consume = await(c, "consume");
    return new Rpc() {
      @Override
      public boolean small(int x) throws Exception {
        return small.call(boolean.class, x);
      }

      @Override
      public int consume(byte[] data) throws Exception {
        return consume.call(int.class, (Object) data);
      }

      @Override
      public void close() {
        c.close();
      }
    };
  }

  static TRADEServiceInfo await(TRADEContainer c, String name) throws Exception {
    long until = System.nanoTime() + 10_000_000_000L;
    TRADEServiceConstraints constraints = new TRADEServiceConstraints().name(name);
    while (true) {
      var found = c.getAvailableServices(constraints);
      if (!found.isEmpty()) {
        return found.iterator().next();
      }
      if (System.nanoTime() > until) {
        throw new IOException("TRADE: service " + name + " did not appear within 10 s");
      }
      Thread.sleep(2);
    }
  }
}
