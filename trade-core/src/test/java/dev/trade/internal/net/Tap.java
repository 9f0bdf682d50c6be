package dev.trade.internal.net;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;

/**
 * A loopback proxy that records every frame passing through it, whole ({@code u32 length | u8
 * version | u8 type | payload}), in both directions: the valid frames of a real session between two
 * containers, for the fuzz tests to mutate. Frames are passed on unchanged (USEENCRYPTION is off,
 * so they can be read). One connection at a time.
 */
final class Tap implements AutoCloseable {
  private final ServerSocket server;
  private final InetSocketAddress target;
  private final List<byte[]> fromDialler = new ArrayList<>();
  private final List<byte[]> fromTarget = new ArrayList<>();
  private final List<Socket> sockets = new ArrayList<>();

  /** Starts listening on a loopback port; connections are passed on to {@code target}. */
  Tap(InetSocketAddress target) throws IOException {
    this.target = target;
    this.server = new ServerSocket(0, 4, InetAddress.getLoopbackAddress());
    Thread t = new Thread(this::accept, "tap-accept");
    t.setDaemon(true);
    t.start();
  }

  /** The address to give a container's CONNECTCONTAINERS. */
  String address() {
    return server.getInetAddress().getHostAddress() + "@" + server.getLocalPort();
  }

  private void accept() {
    try {
      while (true) {
        Socket in = server.accept();
        Socket out = new Socket();
        out.connect(target, 5_000);
        synchronized (this) {
          sockets.add(in);
          sockets.add(out);
        }
        pump(in, out, fromDialler);
        pump(out, in, fromTarget);
      }
    } catch (IOException e) {
      // Closed: the tap's end.
    }
  }

  private void pump(Socket from, Socket to, List<byte[]> record) {
    Thread t = new Thread(() -> {
      try {
        DataInputStream in = new DataInputStream(from.getInputStream());
        OutputStream out = to.getOutputStream();
        while (true) {
          int length = in.readInt();
          byte[] frame = new byte[4 + length];
          ByteBuffer.wrap(frame).putInt(length);
          in.readFully(frame, 4, length);
          synchronized (this) {
            record.add(frame);
          }
          out.write(frame);
          out.flush();
        }
      } catch (IOException e) {
        closeQuietly(to);
      }
    }, "tap-pump");
    t.setDaemon(true);
    t.start();
  }

  /** The frames the dialling container sent so far. */
  synchronized List<byte[]> fromDialler() {
    return List.copyOf(fromDialler);
  }

  /** The frames the target container sent so far. */
  synchronized List<byte[]> fromTarget() {
    return List.copyOf(fromTarget);
  }

  /** Whether a frame of {@code type} has passed in either direction. */
  synchronized boolean saw(int type) {
    return fromDialler.stream().anyMatch(f -> f[5] == type) || fromTarget.stream().anyMatch(f -> f[5] == type);
  }

  private static void closeQuietly(Socket s) {
    try {
      s.close();
    } catch (IOException e) {
      // Closing anyway.
    }
  }

  @Override
  public synchronized void close() throws IOException {
    server.close();
    sockets.forEach(Tap::closeQuietly);
  }
}
