package dev.trade.bench;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;

/**
 * The physical limit: a blocking socket per calling thread and a server thread per socket, with the
 * smallest framing that still carries an operation and a length. No serialization, no pooling, no
 * hand-offs: two thread wake-ups per call, like the kernel's own round trip.
 *
 * <p>Request: {@code u8 op | u32 length | bytes}; reply: one byte (small) or a u32 (consume).
 */
final class RawTcp {
  private static final int SMALL = 1;
  private static final int CONSUME = 2;

  private RawTcp() {}

  static Rpc.Server serve() throws IOException {
    ServerSocket server = new ServerSocket();
    server.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 128);
    Thread acceptor = new Thread(() -> {
      while (!server.isClosed()) {
        try {
          Socket s = server.accept();
          Thread t = new Thread(() -> serveOne(s), "raw-serve");
          t.setDaemon(true);
          t.start();
        } catch (IOException e) {
          return;
        }
      }
    }, "raw-accept");
    acceptor.setDaemon(true);
    acceptor.start();
    return new Rpc.Server() {
      @Override
      public String address() {
        return "127.0.0.1:" + server.getLocalPort();
      }

      @Override
      public void close() throws IOException {
        server.close();
      }
    };
  }

  private static void serveOne(Socket s) {
    try (s) {
      s.setTcpNoDelay(true);
      DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream(), 64 * 1024));
      DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream(), 1024));
      byte[] buf = new byte[1024];
      while (true) {
        int op;
        try {
          op = in.readUnsignedByte();
        } catch (EOFException e) {
          return;
        }
        int length = in.readInt();
        if (length > buf.length) {
          buf = new byte[length];
        }
        in.readFully(buf, 0, length);
        if (op == SMALL) {
          int x = ((buf[0] & 0xff) << 24) | ((buf[1] & 0xff) << 16) | ((buf[2] & 0xff) << 8) | (buf[3] & 0xff);
          out.writeBoolean(Rpc.Service.small(x));
        } else {
          out.writeInt(length);
        }
        out.flush();
      }
    } catch (IOException e) {
      // Client gone.
    }
  }

  static Rpc connect(String address) throws IOException {
    String[] hp = address.split(":");
    return new Client(hp[0], Integer.parseInt(hp[1]));
  }

  private static final class Client implements Rpc {
    private final String host;
    private final int port;
    private final Socket socket;
    private final DataInputStream in;
    private final DataOutputStream out;

    Client(String host, int port) throws IOException {
      this.host = host;
      this.port = port;
      socket = new Socket();
      socket.connect(new InetSocketAddress(host, port), 3000);
      socket.setTcpNoDelay(true);
      in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 1024));
      out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream(), 64 * 1024));
    }

    @Override
    public boolean small(int x) throws IOException {
      out.writeByte(SMALL);
      out.writeInt(4);
      out.writeInt(x);
      out.flush();
      return in.readBoolean();
    }

    @Override
    public int consume(byte[] data) throws IOException {
      out.writeByte(CONSUME);
      out.writeInt(data.length);
      out.write(data);
      out.flush();
      return in.readInt();
    }

    @Override
    public Rpc forCaller() throws IOException {
      return new Client(host, port);
    }

    @Override
    public void close() throws IOException {
      socket.close();
    }
  }
}
