package dev.trade.internal.net.link;

import dev.trade.internal.crypto.HmacSha256;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * The connection handshake: both sides send HELLO (identity and a fresh nonce), then AUTH, an HMAC
 * over both nonces and identities and the sender's role (whether it opened the connection or
 * accepted it), keyed by the shared credentials, proving each holds them without the secret
 * crossing the wire. Until the peer's AUTH checks out nothing but these two small fixed-layout
 * frames is read; no value decoder ever sees unauthenticated bytes.
 *
 * <p>The role is what stops a relay: without it, a party without credentials that opens one
 * connection to each of two containers, posing to each as the other with the other's nonce, could
 * pass each container's AUTH on to the other, and hold two links that both take as authentic.
 * Opened by that party, both connections have two accepting containers, and an accepting side's
 * proof never passes for an opening side's.
 *
 * <p>Holds the identity given at construction and a count of the connections it opened;
 * thread-safe.
 */
public final class Handshake {
  private static final byte[] MAGIC = {'T', 'R', 'D', 'E'};
  private static final int NONCE = 32;
  private static final int MAX_STRING = 255;
  private static final int MAX_ADDRESSES = 16;
  private static final SecureRandom RANDOM = new SecureRandom();
  /** Dial numbers of the connections this side opens: 1, 2, … (see {@link Peer#dial}). */
  private final AtomicLong dials = new AtomicLong();

  /**
   * Who we are, as told to peers; {@code maxFrame} is our MAXFRAMESIZE, or 0 to leave it out of
   * the HELLO (as senders before it was exchanged did).
   */
  public record Identity(String systemId, UUID containerId, String name, String host, List<String> addresses,
      boolean encrypt, boolean digests, int maxFrame) {
    /** An identity that does not encrypt frames and exchanges full state when a link comes up. */
    public Identity(String systemId, UUID containerId, String name, String host, List<String> addresses) {
      this(systemId, containerId, name, host, addresses, false, false, 0);
    }
  }

  /**
   * Who the peer proved to be, the link's frame cipher when frames are encrypted (else null),
   * whether both sides said they exchange DIGEST when the link comes up, and the largest frame the
   * peer said it accepts (its MAXFRAMESIZE; 0 if it did not say), and the connection's dial
   * number: the opening side numbers the connections it opens 1, 2, … in the order it dials them
   * and says the number in its HELLO, so both ends know which of two links it dialled later (0 when
   * the opening side did not say).
   */
  public record Peer(UUID containerId, String name, String host, List<String> addresses, FrameCipher cipher,
      boolean digests, int maxFrame, long dial) {
    Peer(UUID containerId, String name, String host, List<String> addresses, FrameCipher cipher) {
      this(containerId, name, host, addresses, cipher, false, 0, 0);
    }
  }

  /** AUTH role of a side that opened the connection, and of one that accepted it. */
  public static final byte OPENED = 'I';
  static final byte ACCEPTED = 'A';

  /** HELLO flag: this side encrypts frames after the handshake (USEENCRYPTION). */
  private static final int FLAG_ENCRYPT = 1;
  private static final int FLAG_DIGEST = 2;
  /** HELLO flag: a u32 follows the flags, the largest frame this side accepts (MAXFRAMESIZE). */
  private static final int FLAG_FRAME_LIMIT = 4;
  /** HELLO flag: a u64 follows (after the frame limit, if any), the opening side's dial number. */
  private static final int FLAG_DIAL = 8;

  /** The handshake failed; {@code reason} is one of the {@code Wire.REFUSE_*} codes or 0 (I/O). */
  public static final class Failure extends Exception {
    private static final long serialVersionUID = 1L;
    final int reason;

    Failure(int reason, String message) {
      super(message);
      this.reason = reason;
    }
  }

  private final Identity self;
  private final byte[] key;

  /**
   * @throws IllegalArgumentException if the system id, name or host does not fit a handshake field
   *     (255 bytes of UTF-8); the message names the configuration key
   */
  public Handshake(Identity self, String credentials) {
    checkField("TRADESYSID", self.systemId());
    checkField("CONTAINERNAME", self.name());
    checkField("the host name", self.host());
    this.self = self;
    this.key = deriveKey(self.systemId(), credentials);
  }

  private static void checkField(String what, String value) {
    int length = value.getBytes(StandardCharsets.UTF_8).length;
    if (length > MAX_STRING) {
      throw new IllegalArgumentException(what + " is " + length + " bytes long in UTF-8, but the"
          + " connection handshake carries at most " + MAX_STRING + ": " + value);
    }
  }

  /**
   * Runs the handshake over a connected stream pair; the caller sets a read timeout first.
   *
   * @param opened whether this side opened the connection (else it accepted it)
   *
   * @throws Failure with the reason (also sent to the peer as REFUSE when it is ours to tell)
   * @throws IOException when the connection fails or the peer refused us
   */
  public Peer run(InputStream rawIn, OutputStream rawOut, boolean opened) throws IOException, Failure {
    return run(rawIn, rawOut, opened, id -> { });
  }

  /**
   * Runs the handshake as {@link #run(InputStream, OutputStream, boolean)} does.
   *
   * @param heard told the peer's container id once its HELLO checked out, before this side's AUTH
   *     is sent: the peer cannot have finished its side of the handshake before
   */
  Peer run(InputStream rawIn, OutputStream rawOut, boolean opened, Consumer<UUID> heard)
      throws IOException, Failure {
    return run(rawIn, rawOut, opened ? dials.incrementAndGet() : 0, heard);
  }

  /**
   * Runs the handshake with a given dial number (tests that dial out of order).
   *
   * @param dial this connection's dial number if this side opened it (positive), else 0
   */
  public Peer run(InputStream rawIn, OutputStream rawOut, long dial) throws IOException, Failure {
    return run(rawIn, rawOut, dial, id -> { });
  }

  private Peer run(InputStream rawIn, OutputStream rawOut, long dial, Consumer<UUID> heard)
      throws IOException, Failure {
    boolean opened = dial > 0;
    DataInputStream in = new DataInputStream(rawIn);
    DataOutputStream out = new DataOutputStream(rawOut);
    byte[] nonce = new byte[NONCE];
    RANDOM.nextBytes(nonce);
    writeFrame(out, Wire.HELLO, hello(nonce, dial));

    ByteBuffer hello = readFrame(in, Wire.HELLO);
    Peer peer;
    byte[] peerNonce = new byte[NONCE];
    String peerSystem;
    int peerFlags;
    try {
      byte[] magic = new byte[4];
      hello.get(magic);
      if (!MessageDigest.isEqual(magic, MAGIC)) {
        throw refuse(out, Wire.REFUSE_MALFORMED, "not a TRADE container (bad magic)");
      }
      int version = hello.get() & 0xff;
      if (version != Wire.VERSION) {
        throw refuse(out, Wire.REFUSE_VERSION, "protocol version " + version + ", we speak " + Wire.VERSION);
      }
      peerSystem = string(hello);
      UUID id = new UUID(hello.getLong(), hello.getLong());
      String name = string(hello);
      String host = string(hello);
      int count = hello.get() & 0xff;
      if (count > MAX_ADDRESSES) {
        throw refuse(out, Wire.REFUSE_MALFORMED, "too many addresses: " + count);
      }
      List<String> addresses = new ArrayList<>(count);
      for (int i = 0; i < count; i++) {
        addresses.add(string(hello));
      }
      hello.get(peerNonce);
      peerFlags = hello.get() & 0xff;
      int peerMaxFrame = 0;
      if ((peerFlags & FLAG_FRAME_LIMIT) != 0) {
        peerMaxFrame = hello.getInt();
        if (peerMaxFrame < Wire.MIN_FRAME_LIMIT) {
          throw refuse(out, Wire.REFUSE_MALFORMED, "frame limit " + Integer.toUnsignedString(
              peerMaxFrame) + " below " + Wire.MIN_FRAME_LIMIT);
        }
      }
      long peerDial = (peerFlags & FLAG_DIAL) != 0 ? hello.getLong() : 0;
      peer = new Peer(id, name, host, addresses, null,
          self.digests() && (peerFlags & FLAG_DIGEST) != 0, peerMaxFrame, opened ? dial : peerDial);
    } catch (RuntimeException e) { // BufferUnderflow, bad UTF-8 length...
      throw refuse(out, Wire.REFUSE_MALFORMED, "malformed HELLO: " + e);
    }
    if (!peerSystem.equals(self.systemId())) {
      throw refuse(out, Wire.REFUSE_SYSTEM, "other system id '" + peerSystem + "' (ours is '"
          + self.systemId() + "')");
    }
    if (peer.containerId().equals(self.containerId())) {
      throw refuse(out, Wire.REFUSE_SELF, "connected to itself");
    }
    boolean peerEncrypts = (peerFlags & FLAG_ENCRYPT) != 0;
    if (peerEncrypts != self.encrypt()) {
      throw refuse(out, Wire.REFUSE_ENCRYPTION, "USEENCRYPTION differs: " + self.encrypt()
          + " here, " + peerEncrypts + " at " + peer.name());
    }
    heard.accept(peer.containerId());
    byte role = opened ? OPENED : ACCEPTED;
    byte peerRole = opened ? ACCEPTED : OPENED;
    writeFrame(out, Wire.AUTH, mac(role, nonce, peerNonce, self.containerId(), peer.containerId()));
    ByteBuffer auth = readFrame(in, Wire.AUTH);
    byte[] proof = new byte[auth.remaining()];
    auth.get(proof);
    byte[] expected = mac(peerRole, peerNonce, nonce, peer.containerId(), self.containerId());
    if (!MessageDigest.isEqual(proof, expected)) {
      throw refuse(out, Wire.REFUSE_CREDENTIALS, "authentication failed: wrong CREDENTIALS on one side");
    }
    if (!self.encrypt()) {
      return peer;
    }
    return new Peer(peer.containerId(), peer.name(), peer.host(), peer.addresses(),
        new FrameCipher(key, self.containerId(), peer.containerId(), nonce, peerNonce), peer.digests(),
        peer.maxFrame(), peer.dial());
  }

  /** The HELLO payload with this nonce, and this dial number if positive (see {@link Peer#dial}). */
  public byte[] hello(byte[] nonce, long dial) throws IOException {
    ByteArrayOutputStream bytes = new ByteArrayOutputStream(256);
    DataOutputStream out = new DataOutputStream(bytes);
    out.write(MAGIC);
    out.writeByte(Wire.VERSION);
    writeString(out, self.systemId());
    out.writeLong(self.containerId().getMostSignificantBits());
    out.writeLong(self.containerId().getLeastSignificantBits());
    writeString(out, self.name());
    writeString(out, self.host());
    List<String> addresses = self.addresses().subList(0, Math.min(MAX_ADDRESSES, self.addresses().size()));
    out.writeByte(addresses.size());
    for (String a : addresses) {
      writeString(out, a);
    }
    out.write(nonce);
    boolean limit = self.maxFrame() > 0;
    out.writeByte((self.encrypt() ? FLAG_ENCRYPT : 0) | (self.digests() ? FLAG_DIGEST : 0)
        | (limit ? FLAG_FRAME_LIMIT : 0) | (dial > 0 ? FLAG_DIAL : 0));
    if (limit) {
      out.writeInt(self.maxFrame());
    }
    if (dial > 0) {
      out.writeLong(dial);
    }
    return bytes.toByteArray();
  }

  /**
   * The AUTH payload that {@code sender}, in {@code senderRole} ({@link #OPENED} or
   * {@link #ACCEPTED}), sends to {@code receiver}.
   */
  public byte[] mac(byte senderRole, byte[] senderNonce, byte[] receiverNonce, UUID sender, UUID receiver) {
    return new HmacSha256(key)
        .update("TRADE-auth-v2".getBytes(StandardCharsets.US_ASCII))
        .update(self.systemId().getBytes(StandardCharsets.UTF_8))
        .update(senderRole)
        .update(uuid(sender))
        .update(uuid(receiver))
        .update(senderNonce)
        .update(receiverNonce)
        .doFinal();
  }

  /** {@code SHA-256("TRADE-credentials-v1" 0x00 systemId 0x00 credentials)}. */
  public static byte[] deriveKey(String systemId, String credentials) {
    try {
      MessageDigest sha = MessageDigest.getInstance("SHA-256");
      sha.update("TRADE-credentials-v1".getBytes(StandardCharsets.US_ASCII));
      sha.update((byte) 0);
      sha.update(systemId.getBytes(StandardCharsets.UTF_8));
      sha.update((byte) 0);
      sha.update(credentials.getBytes(StandardCharsets.UTF_8));
      return sha.digest();
    } catch (GeneralSecurityException e) {
      throw new IllegalStateException("SHA-256 is part of every JDK", e);
    }
  }

  private static byte[] uuid(UUID id) {
    return ByteBuffer.allocate(16).putLong(id.getMostSignificantBits())
        .putLong(id.getLeastSignificantBits()).array();
  }

  private static Failure refuse(DataOutputStream out, int reason, String message) {
    try {
      byte[] text = message.getBytes(StandardCharsets.UTF_8);
      int len = Math.min(text.length, 1000);
      ByteBuffer b = ByteBuffer.allocate(3 + len);
      b.put((byte) reason).putShort((short) len).put(text, 0, len);
      writeFrame(out, Wire.REFUSE, b.array());
    } catch (IOException ignored) {
      // The peer is gone already; our own log line still says why.
    }
    return new Failure(reason, message);
  }

  public static void writeFrame(DataOutputStream out, int type, byte[] payload) throws IOException {
    out.writeInt(2 + payload.length);
    out.writeByte(Wire.VERSION);
    out.writeByte(type);
    out.write(payload);
    out.flush();
  }

  /** Reads one small frame of the expected type; a REFUSE from the peer becomes an IOException. */
  private static ByteBuffer readFrame(DataInputStream in, int expected) throws IOException, Failure {
    int length;
    try {
      length = in.readInt();
    } catch (EOFException e) {
      throw new IOException("peer closed the connection during the handshake");
    }
    if (length < 2 || length > Wire.MAX_HANDSHAKE_FRAME) {
      throw new Failure(Wire.REFUSE_MALFORMED, "bad handshake frame length " + length);
    }
    byte[] frame = new byte[length];
    try {
      in.readFully(frame);
    } catch (EOFException e) {
      throw new IOException("peer closed the connection during the handshake");
    }
    ByteBuffer b = ByteBuffer.wrap(frame);
    int version = b.get() & 0xff;
    int type = b.get() & 0xff;
    if (type == Wire.REFUSE && b.remaining() >= 3) {
      int reason = b.get() & 0xff;
      int len = Math.min(b.getShort() & 0xffff, b.remaining());
      byte[] text = new byte[len];
      b.get(text);
      throw new IOException("refused by peer (reason " + reason + "): " + printable(text));
    }
    if (version != Wire.VERSION && type == Wire.HELLO) {
      // Let the HELLO parser report the version mismatch with both numbers.
      return b.position(2);
    }
    if (type != expected) {
      throw new Failure(Wire.REFUSE_MALFORMED, "expected handshake frame " + expected + ", got " + type);
    }
    return b;
  }

  private static void writeString(DataOutputStream out, String s) throws IOException {
    byte[] b = s.getBytes(StandardCharsets.UTF_8);
    if (b.length > MAX_STRING) {
      throw new IllegalArgumentException("too long for a handshake field (" + b.length + " bytes): " + s);
    }
    out.writeByte(b.length);
    out.write(b);
  }

  private static String string(ByteBuffer b) {
    int len = b.get() & 0xff;
    byte[] bytes = new byte[len];
    b.get(bytes);
    return printable(bytes);
  }

  /**
   * UTF-8 text with each control character shown as '?': what a peer names, authenticated or not,
   * ends up in log lines, and a line break in it would forge lines of its own. Settings refuse
   * control characters in names and ids, so a well-behaved peer's text is unchanged.
   */
  private static String printable(byte[] bytes) {
    String s = new String(bytes, StandardCharsets.UTF_8);
    StringBuilder out = new StringBuilder(s.length());
    s.codePoints().forEach(c -> out.appendCodePoint(Character.isISOControl(c) ? '?' : c));
    return out.toString();
  }
}
