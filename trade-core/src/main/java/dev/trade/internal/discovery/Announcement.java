package dev.trade.internal.discovery;

import java.net.Inet6Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Objects;

/**
 * What one container tells the others by multicast: "container {@code containerId} of system
 * {@code systemId} can be reached at {@code addresses}".
 *
 * <p>An announcement is a value: the constructor checks every field against the limits of the
 * wire format, so any instance can be encoded and a decoded packet always yields a valid
 * instance. The wire format itself is documented in {@link Packets} and {@code docs/discovery.md}.
 * Immutable and therefore thread-safe.
 *
 * @param protocolVersion always {@link Packets#VERSION}
 * @param systemId the system id ({@code TRADESYSID}): 1 to {@value Packets#MAX_SYSTEM_ID} bytes of
 *     UTF-8, no control characters
 * @param containerId the sender's id, unique per container incarnation: 1 to
 *     {@value Packets#MAX_CONTAINER_ID} bytes of UTF-8, no control characters
 * @param containerName the sender's name, for logs: 1 to {@value Packets#MAX_CONTAINER_NAME} bytes
 *     of UTF-8, no control characters
 * @param addresses where the sender accepts connections: at most {@value Packets#MAX_ADDRESSES},
 *     each a resolved, concrete unicast address with a port from 1 to 65535; never a wildcard, a
 *     multicast or an IPv6 link-local address (its scope cannot travel). May be empty.
 * @param sequence positive; grows with every packet a container sends
 * @param timestampMillis the sender's clock when it sent the packet, ms since the epoch, not negative
 */
public record Announcement(int protocolVersion, String systemId, String containerId,
    String containerName, List<InetSocketAddress> addresses, long sequence, long timestampMillis) {

  /**
   * Checks every field (see the class documentation).
   *
   * @throws NullPointerException if a string, the list or an address in it is null
   * @throws IllegalArgumentException if a field breaks a limit; the message names the field
   */
  public Announcement {
    if (protocolVersion != Packets.VERSION) {
      throw new IllegalArgumentException("protocol version " + protocolVersion
          + " is not supported (only " + Packets.VERSION + ")");
    }
    checkText(systemId, "system id", Packets.MAX_SYSTEM_ID);
    checkText(containerId, "container id", Packets.MAX_CONTAINER_ID);
    checkText(containerName, "container name", Packets.MAX_CONTAINER_NAME);
    addresses = List.copyOf(Objects.requireNonNull(addresses, "addresses == null"));
    if (addresses.size() > Packets.MAX_ADDRESSES) {
      throw new IllegalArgumentException(addresses.size() + " addresses, more than "
          + Packets.MAX_ADDRESSES);
    }
    for (InetSocketAddress a : addresses) {
      checkAddress(a);
    }
    if (sequence <= 0) {
      throw new IllegalArgumentException("sequence " + sequence + " is not positive");
    }
    if (timestampMillis < 0) {
      throw new IllegalArgumentException("timestamp " + timestampMillis + " is negative");
    }
  }

  /**
   * This announcement as one datagram, signed with {@code key}.
   *
   * @param key from {@link Packets#deriveKey(String, String)} for this announcement's system id
   */
  byte[] encode(byte[] key) {
    return Packets.encode(this, key);
  }

  /**
   * Checks and reads one datagram; see {@link Packets#decode(byte[], int, String, byte[])}.
   *
   * @throws BadPacketException if the packet is not a valid announcement of {@code systemId}
   *     signed with {@code key}
   */
  static Announcement decode(byte[] packet, int len, String systemId, byte[] key)
      throws BadPacketException {
    return Packets.decode(packet, len, systemId, key);
  }

  /** Whether {@code a} may be announced: concrete, unicast, with a port; no IPv6 scope needed. */
  static boolean isAnnounceable(InetAddress a) {
    return !a.isAnyLocalAddress() && !a.isMulticastAddress()
        && !(a instanceof Inet6Address && a.isLinkLocalAddress());
  }

  /** {@code 10.0.0.5:4000} or {@code [fd00::1]:4000}: the form logs and docs use. */
  static String format(InetSocketAddress a) {
    if (a.isUnresolved()) {
      return a.getHostString() + ":" + a.getPort();
    }
    String host = a.getAddress().getHostAddress();
    return (a.getAddress() instanceof Inet6Address ? "[" + host + "]" : host) + ":" + a.getPort();
  }

  /** {@code [10.0.0.5:4000, [fd00::1]:4000]}. */
  static String format(List<InetSocketAddress> list) {
    StringBuilder out = new StringBuilder("[");
    for (InetSocketAddress a : list) {
      out.append(out.length() > 1 ? ", " : "").append(format(a));
    }
    return out.append(']').toString();
  }

  /** For logs: {@code container 'arm' (id) of system 'diarc' at [10.0.0.5:4000], seq 7, ...}. */
  @Override
  public String toString() {
    return "container '" + containerName + "' (" + containerId + ") of system '" + systemId
        + "' at " + format(addresses) + ", seq " + sequence + ", time " + timestampMillis;
  }

  private static void checkAddress(InetSocketAddress a) {
    Objects.requireNonNull(a, "address == null");
    String text = format(a);
    if (a.isUnresolved()) {
      throw new IllegalArgumentException("address " + text + " is not resolved");
    }
    if (a.getAddress().isAnyLocalAddress()) {
      throw new IllegalArgumentException("address " + text
          + " is a wildcard: announce the concrete addresses of each interface");
    }
    if (!isAnnounceable(a.getAddress())) {
      throw new IllegalArgumentException("address " + text
          + " cannot be announced: multicast, or IPv6 link-local");
    }
    if (a.getPort() == 0) {
      throw new IllegalArgumentException("address " + text + " has port 0");
    }
  }

  static void checkText(String s, String field, int maxBytes) {
    Objects.requireNonNull(s, field + " == null");
    if (s.isEmpty()) {
      throw new IllegalArgumentException(field + " is empty");
    }
    for (int i = 0; i < s.length(); i++) {
      // Control characters would let a peer forge log lines, and NUL would make the key
      // derivation ambiguous.
      if (Character.isISOControl(s.charAt(i))) {
        throw new IllegalArgumentException(field + " contains a control character at index " + i);
      }
    }
    int bytes;
    try {
      bytes = StandardCharsets.UTF_8.newEncoder().encode(CharBuffer.wrap(s)).remaining();
    } catch (CharacterCodingException e) {
      throw new IllegalArgumentException(field + " is not valid Unicode (lone surrogate)");
    }
    if (bytes > maxBytes) {
      throw new IllegalArgumentException(field + " is " + bytes + " bytes of UTF-8, more than "
          + maxBytes);
    }
  }
}
