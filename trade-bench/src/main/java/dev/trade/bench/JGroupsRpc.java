package dev.trade.bench;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Method;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import org.jgroups.Address;
import org.jgroups.JChannel;
import org.jgroups.Message;
import org.jgroups.blocks.MethodCall;
import org.jgroups.blocks.RequestOptions;
import org.jgroups.blocks.RpcDispatcher;

/**
 * JGroups RpcDispatcher between two members (the server JVM and the client JVM) on the stack in
 * {@code jgroups-loopback.xml}: loopback TCP, TCPPING, no multicast. Calls are synchronous unicast
 * RPCs to the other member with a 30 s timeout, flagged OOB as JGroups advises for independent
 * concurrent requests (otherwise requests from one member are delivered one at a time, in order).
 */
final class JGroupsRpc {
  private static final String CLUSTER = "trade-bench";

  /** The target object; public so that JGroups can invoke it reflectively. */
  public static final class Impl {
    public boolean small(int x) {
      return Rpc.Service.small(x);
    }

    public int consume(byte[] data) {
      return Rpc.Service.consume(data);
    }
  }

  private static final Method SMALL;
  private static final Method CONSUME;

  static {
    try {
      SMALL = Impl.class.getMethod("small", int.class);
      CONSUME = Impl.class.getMethod("consume", byte[].class);
    } catch (NoSuchMethodException e) {
      throw new ExceptionInInitializerError(e);
    }
  }

  private JGroupsRpc() {}

  private static int freePort() throws IOException {
    try (ServerSocket s = new ServerSocket()) {
      s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
      return s.getLocalPort();
    }
  }

  private static JChannel channel(int port, String hosts) throws Exception {
    System.setProperty("bench.jgroups.port", Integer.toString(port));
    System.setProperty("bench.jgroups.hosts", hosts);
    try (InputStream config = JGroupsRpc.class.getResourceAsStream("/jgroups-loopback.xml")) {
      return new JChannel(config).name("bench-" + port);
    }
  }

  static Rpc.Server serve() throws Exception {
    int port = freePort();
    JChannel ch = channel(port, "127.0.0.1[" + port + "]");
    RpcDispatcher dispatcher = new RpcDispatcher(ch, new Impl());
    ch.connect(CLUSTER);
    return new Rpc.Server() {
      @Override
      public String address() {
        return "127.0.0.1[" + port + "]";
      }

      @Override
      public void close() throws IOException {
        dispatcher.close();
        ch.close();
      }
    };
  }

  static Rpc connect(String address) throws Exception {
    JChannel ch = channel(freePort(), address);
    RpcDispatcher dispatcher = new RpcDispatcher(ch, new Impl());
    ch.connect(CLUSTER);
    long until = System.nanoTime() + 10_000_000_000L;
    while (ch.getView().size() < 2) {
      if (System.nanoTime() > until) {
        throw new IOException("JGroups: the server did not join within 10 s: " + ch.getView());
      }
      Thread.sleep(10);
    }
    Address server = ch.getView().getMembers().stream()
        .filter(a -> !a.equals(ch.getAddress())).findFirst().orElseThrow();
    RequestOptions options = RequestOptions.SYNC().timeout(30_000).flags(Message.Flag.OOB);
    return new Rpc() {
      @Override
      public boolean small(int x) throws Exception {
        Boolean r = dispatcher.callRemoteMethod(server, new MethodCall(SMALL, x), options);
        return r;
      }

      @Override
      public int consume(byte[] data) throws Exception {
        Integer r = dispatcher.callRemoteMethod(server, new MethodCall(CONSUME, data), options);
        return r;
      }

      @Override
      public void close() throws IOException {
        dispatcher.close();
        ch.close();
      }
    };
  }
}
