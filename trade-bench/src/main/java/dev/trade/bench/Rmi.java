package dev.trade.bench;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.rmi.Remote;
import java.rmi.RemoteException;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.rmi.server.RMIServerSocketFactory;
import java.rmi.server.UnicastRemoteObject;

/**
 * JDK RMI, as TRADE's predecessor used it: a registry and an exported object, both listening on
 * 127.0.0.1 only (a server socket factory binds them there; {@code java.rmi.server.hostname} makes
 * the stub name the same address). Calls use RMI's own connection pool.
 */
final class Rmi {
  private static final String NAME = "bench";

  /** The remote interface. */
  public interface Api extends Remote {
    boolean small(int x) throws RemoteException;

    int consume(byte[] data) throws RemoteException;
  }

  private static final class Impl implements Api {
    @Override
    public boolean small(int x) {
      return Rpc.Service.small(x);
    }

    @Override
    public int consume(byte[] data) {
      return Rpc.Service.consume(data);
    }
  }

  /** Binds server sockets to loopback only. */
  private static final class LoopbackOnly implements RMIServerSocketFactory {
    @Override
    public ServerSocket createServerSocket(int port) throws IOException {
      ServerSocket s = new ServerSocket();
      s.setReuseAddress(true);
      s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port), 128);
      return s;
    }

    @Override
    public boolean equals(Object o) {
      return o instanceof LoopbackOnly;
    }

    @Override
    public int hashCode() {
      return 1;
    }
  }

  private Rmi() {}

  static Rpc.Server serve() throws IOException {
    System.setProperty("java.rmi.server.hostname", "127.0.0.1");
    int port;
    try (ServerSocket probe = new LoopbackOnly().createServerSocket(0)) {
      port = probe.getLocalPort();
    }
    LoopbackOnly factory = new LoopbackOnly();
    Registry registry = LocateRegistry.createRegistry(port, null, factory);
    Impl impl = new Impl();
    Remote stub = UnicastRemoteObject.exportObject(impl, 0, null, factory);
    registry.rebind(NAME, stub);
    int registryPort = port;
    return new Rpc.Server() {
      @Override
      public String address() {
        return "127.0.0.1:" + registryPort;
      }

      @Override
      public void close() throws Exception {
        UnicastRemoteObject.unexportObject(impl, true);
        UnicastRemoteObject.unexportObject(registry, true);
      }
    };
  }

  static Rpc connect(String address) throws Exception {
    System.setProperty("java.rmi.server.hostname", "127.0.0.1");
    String[] hp = address.split(":");
    Api api = (Api) LocateRegistry.getRegistry(hp[0], Integer.parseInt(hp[1])).lookup(NAME);
    return new Rpc() {
      @Override
      public boolean small(int x) throws RemoteException {
        return api.small(x);
      }

      @Override
      public int consume(byte[] data) throws RemoteException {
        return api.consume(data);
      }

      @Override
      public void close() {}
    };
  }
}
