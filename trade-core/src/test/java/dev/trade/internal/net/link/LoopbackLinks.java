package dev.trade.internal.net.link;

import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;

/**
 * Links over loopback socket pairs, not started (nothing reads them unless a test starts them),
 * for tests that look at what a container writes to its neighbours (on loopback, what is written
 * is at the far end when the write returns) or at how a link reads. {@link #close} closes them all.
 */
public final class LoopbackLinks implements AutoCloseable {
  private final List<Socket> sockets = new ArrayList<>();
  private final List<Link> links = new ArrayList<>();

  /**
   * A link to a neighbour with this id and name.
   *
   * @param far gets, at index 0, what the neighbour reads; a read that waits 5 s fails
   */
  public Link link(UUID id, String name, InputStream[] far) throws IOException {
    Socket[] other = new Socket[1];
    Link link = link(id, name, other);
    far[0] = other[0].getInputStream();
    return link;
  }

  /**
   * A link to a neighbour with this id and name.
   *
   * @param far gets, at index 0, the neighbour's socket; a read that waits 5 s fails
   */
  public Link link(UUID id, String name, Socket[] far) throws IOException {
    return link(id, name, far, new ReadRole());
  }

  /**
   * A link to a neighbour with this id and name, read as {@code role} decides.
   *
   * @param far gets, at index 0, the neighbour's socket; a read that waits 5 s fails
   */
  public Link link(UUID id, String name, Socket[] far, ReadRole role) throws IOException {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      Socket near = new Socket();
      near.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), server.getLocalPort()));
      Socket other = server.accept();
      sockets.add(near);
      sockets.add(other);
      other.setSoTimeout(5_000); // a frame that went elsewhere fails the read, not hangs it
      far[0] = other;
      Link link = new Link(near, new Handshake.Peer(id, name, "host", List.of(), null), true,
          1 << 20, role);
      links.add(link);
      return link;
    }
  }

  @Override
  public void close() throws IOException {
    links.forEach(l -> l.close("done"));
    for (Socket s : sockets) {
      s.close();
    }
  }
}
