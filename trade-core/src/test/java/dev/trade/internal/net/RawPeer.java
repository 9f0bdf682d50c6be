package dev.trade.internal.net;

import dev.trade.TRADEContainer;
import dev.trade.TRADEServiceConstraints;
import dev.trade.internal.net.link.Handshake;
import dev.trade.internal.net.link.Wire;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.List;
import java.util.UUID;

/**
 * A peer driven by hand over a loopback socket: it sends whatever bytes a test gives it, and can
 * run the real {@link Handshake} first to get past authentication.
 */
final class RawPeer implements AutoCloseable {
  final Socket socket;
  final UUID id;
  private final InputStream in;
  private final OutputStream out;

  private RawPeer(Socket socket, UUID id) throws IOException {
    this.socket = socket;
    this.id = id;
    this.in = socket.getInputStream();
    this.out = socket.getOutputStream();
  }

  /**
   * The id of the first service a test registers in {@code c}: the container's own system
   * services (group trade.system) were registered before it, at start, and took the first ids.
   */
  static long firstUserServiceId(TRADEContainer c) {
    return 1 + c.getAvailableServices(new TRADEServiceConstraints().inGroups("trade.system")).stream()
        .filter(s -> s.getContainerId().equals(c.getId())).count();
  }

  /** Connects to the first address {@code container} listens on. */
  static RawPeer connect(TRADEContainer container) throws IOException {
    return connect(container, UUID.randomUUID());
  }

  /** Connects to the first address {@code container} listens on, to pose as container {@code id}. */
  static RawPeer connect(TRADEContainer container, UUID id) throws IOException {
    String[] at = container.getServerAddresses().get(0).split("@");
    return connect(new InetSocketAddress(at[0], Integer.parseInt(at[1])), id);
  }

  static RawPeer connect(InetSocketAddress address) throws IOException {
    return connect(address, UUID.randomUUID());
  }

  private static RawPeer connect(InetSocketAddress address, UUID id) throws IOException {
    Socket s = new Socket();
    s.connect(address, 5_000);
    s.setTcpNoDelay(true);
    return new RawPeer(s, id);
  }

  /** Authenticates as container {@link #id} named {@code name}; returns who answered. */
  Handshake.Peer handshake(String systemId, String credentials, String name)
      throws IOException, Handshake.Failure {
    return shake(new Handshake(
        new Handshake.Identity(systemId, id, name, "localhost", List.of()), credentials), 1);
  }

  /**
   * Authenticates as {@link #handshake(String)} does, saying in its HELLO that it exchanges DIGEST
   * when the link comes up.
   */
  Handshake.Peer handshakeWithDigests(String name) throws IOException, Handshake.Failure {
    return shake(new Handshake(
        new Handshake.Identity("diarc", id, name, "localhost", List.of(), false, true, 0), "diarcUser"), 1);
  }

  /** Authenticates with the default TRADESYSID and CREDENTIALS. */
  Handshake.Peer handshake(String name) throws IOException, Handshake.Failure {
    return handshake("diarc", "diarcUser", name);
  }

  /**
   * Authenticates with the default TRADESYSID and CREDENTIALS, saying that this is the {@code
   * dial}th connection its container opened (see {@link Handshake.Peer#dial}).
   */
  Handshake.Peer handshake(String name, long dial) throws IOException, Handshake.Failure {
    return shake(new Handshake(
        new Handshake.Identity("diarc", id, name, "localhost", List.of()), "diarcUser"), dial);
  }

  /** A handshake {@link #begin} began: what {@link #finish} needs. */
  record Begun(Handshake handshake, byte[] nonce, byte[] theirNonce, UUID theirId) {}

  /**
   * Begins a handshake as container {@link #id} named {@code name}, saying that this is the
   * {@code dial}th connection it opened: sends our HELLO and reads the container's HELLO and AUTH.
   * The container has then counted the handshake as one with us, and waits for our AUTH.
   */
  Begun begin(String name, long dial) throws IOException {
    Handshake h = new Handshake(new Handshake.Identity("diarc", id, name, "localhost", List.of()),
        "diarcUser");
    byte[] nonce = new byte[32];
    send(frame(Wire.HELLO, h.hello(nonce, dial)));
    byte[] hello = readFrame();
    if (hello[0] != Wire.HELLO) {
      throw new IOException("expected HELLO, got frame type " + hello[0]);
    }
    ByteBuffer b = ByteBuffer.wrap(hello, 1, hello.length - 1);
    b.position(b.position() + 5); // magic, version
    skipString(b); // system id
    UUID theirs = new UUID(b.getLong(), b.getLong());
    skipString(b); // name
    skipString(b); // host
    for (int n = b.get() & 0xff; n > 0; n--) {
      skipString(b);
    }
    byte[] theirNonce = new byte[32];
    b.get(theirNonce);
    if (readFrame()[0] != Wire.AUTH) { // sent once it read our HELLO
      throw new IOException("expected AUTH");
    }
    return new Begun(h, nonce, theirNonce, theirs);
  }

  /** Sends our AUTH: the container's side of the handshake {@link #begin} began ends. */
  void finish(Begun b) {
    send(frame(Wire.AUTH, b.handshake().mac(Handshake.OPENED, b.nonce(), b.theirNonce(), id,
        b.theirId())));
  }

  private static void skipString(ByteBuffer b) {
    int length = b.get() & 0xff;
    b.position(b.position() + length);
  }

  private Handshake.Peer shake(Handshake h, long dial) throws IOException, Handshake.Failure {
    socket.setSoTimeout(5_000);
    Handshake.Peer peer = h.run(in, out, dial);
    socket.setSoTimeout(0);
    return peer;
  }

  /** Sends bytes; a connection the other side has closed already is not an error here. */
  void send(byte[] bytes) {
    try {
      out.write(bytes);
      out.flush();
    } catch (IOException e) {
      // Closed by the other side: what the caller checks next.
    }
  }

  /**
   * Whether the other side has closed the connection, judged without waiting: reads and discards
   * what has arrived.
   */
  boolean isClosedNow() throws IOException {
    byte[] sink = new byte[8192];
    while (in.available() > 0) {
      if (in.read(sink) < 0) {
        return true;
      }
    }
    socket.setSoTimeout(1);
    try {
      return in.read(sink) < 0;
    } catch (SocketTimeoutException e) {
      return false;
    } catch (SocketException e) {
      return true;
    }
  }

  /** Reads one frame: {@code [type, payload...]}. */
  byte[] readFrame() throws IOException {
    socket.setSoTimeout(5_000);
    DataInputStream data = new DataInputStream(in);
    int length = data.readInt();
    data.readUnsignedByte(); // version
    byte[] typeAndPayload = new byte[length - 1];
    data.readFully(typeAndPayload);
    return typeAndPayload;
  }

  /**
   * Reads and discards until the other side closes the connection, and returns how long that took.
   *
   * @throws AssertionError if it is still open after {@code timeout}
   */
  Duration awaitClosed(Duration timeout) throws IOException {
    long start = System.nanoTime();
    long deadline = start + timeout.toNanos();
    byte[] sink = new byte[8192];
    while (true) {
      long left = deadline - System.nanoTime();
      if (left <= 0) {
        throw new AssertionError("connection still open after " + timeout.toMillis() + " ms");
      }
      socket.setSoTimeout((int) Math.max(1, left / 1_000_000));
      try {
        if (in.read(sink) < 0) {
          break;
        }
      } catch (SocketTimeoutException e) {
        // Loop: the deadline check fails the test.
      } catch (SocketException | EOFException e) { // reset: closed with our bytes unread
        break;
      }
    }
    return Duration.ofNanos(System.nanoTime() - start);
  }

  @Override
  public void close() throws IOException {
    socket.close();
  }

  /** A frame as the protocol lays it out, with any length, version and type. */
  static byte[] frame(int length, int version, int type, byte[] payload) {
    return ByteBuffer.allocate(6 + payload.length).putInt(length).put((byte) version)
        .put((byte) type).put(payload).array();
  }

  /** A well-formed frame of {@code type}. */
  static byte[] frame(int type, byte[] payload) {
    return frame(2 + payload.length, Wire.VERSION, type, payload);
  }
}
