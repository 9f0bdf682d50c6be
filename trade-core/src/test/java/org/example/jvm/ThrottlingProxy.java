package org.example.jvm;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.locks.LockSupport;

/**
 * A TCP relay on loopback that passes bytes from its clients to a target at a fixed rate (and the
 * replies unthrottled), to stand for a slow network link. Closing it closes every connection.
 */
final class ThrottlingProxy implements AutoCloseable {
  private static final int CHUNK = 8 * 1024;

  private final InetSocketAddress target;
  private final long bytesPerSecond;
  private final ServerSocket server;
  private final List<Socket> sockets = new CopyOnWriteArrayList<>();
  /** While set and not counted down, nothing passes towards the target. */
  private volatile CountDownLatch paused;

  ThrottlingProxy(InetSocketAddress target, long bytesPerSecond) throws IOException {
    this.target = target;
    this.bytesPerSecond = bytesPerSecond;
    this.server = new ServerSocket(0, 16, InetAddress.getLoopbackAddress());
    start(this::acceptLoop, "proxy-accept");
  }

  /** Where clients connect, as {@code ip@port}. */
  String address() {
    return server.getInetAddress().getHostAddress() + "@" + server.getLocalPort();
  }

  private void acceptLoop() {
    try {
      while (true) {
        Socket client = server.accept();
        Socket upstream = new Socket(target.getAddress(), target.getPort());
        sockets.add(client);
        sockets.add(upstream);
        start(() -> pump(client, upstream, bytesPerSecond, this::gate), "proxy-up");
        start(() -> pump(upstream, client, 0, () -> { }), "proxy-down");
      }
    } catch (IOException e) {
      // Closed.
    }
  }

  /** Stops passing bytes towards the target (the link's peer takes nothing) until {@link #resume}. */
  void pause() {
    paused = new CountDownLatch(1);
  }

  /** Whether {@link #pause} holds bytes back now. */
  boolean isPaused() {
    CountDownLatch p = paused;
    return p != null && p.getCount() > 0;
  }

  void resume() {
    CountDownLatch p = paused;
    if (p != null) {
      p.countDown();
    }
  }

  /** Returns once bytes may pass towards the target. */
  private void gate() {
    CountDownLatch p = paused;
    if (p != null) {
      try {
        p.await();
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }

  /**
   * Copies {@code from} to {@code to}, at most {@code rate} bytes a second (0: unlimited), each
   * chunk once {@code gate} returns.
   */
  private static void pump(Socket from, Socket to, long rate, Runnable gate) {
    byte[] buffer = new byte[CHUNK];
    long due = System.nanoTime();
    try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
      while (true) {
        gate.run();
        int n = in.read(buffer);
        if (n < 0) {
          break;
        }
        out.write(buffer, 0, n);
        out.flush();
        if (rate > 0) {
          // Pace the link: the next chunk leaves once this one has had its time on the wire (an
          // idle link saves up no credit).
          due = Math.max(due, System.nanoTime()) + n * 1_000_000_000L / rate;
          for (long now = System.nanoTime(); now < due; now = System.nanoTime()) {
            LockSupport.parkNanos(due - now);
          }
        }
      }
    } catch (IOException e) {
      // One side closed; closing both ends the other pump too.
    } finally {
      closeQuietly(from);
      closeQuietly(to);
    }
  }

  @Override
  public void close() {
    resume();
    try {
      server.close();
    } catch (IOException ignored) {
      // Closing anyway.
    }
    sockets.forEach(ThrottlingProxy::closeQuietly);
  }

  private static void closeQuietly(Socket s) {
    try {
      s.close();
    } catch (IOException ignored) {
      // Closing anyway.
    }
  }

  private static void start(Runnable r, String name) {
    Thread t = new Thread(r, name);
    t.setDaemon(true);
    t.start();
  }
}
