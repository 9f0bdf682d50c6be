package dev.trade;

import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.io.Serializable;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.util.Arrays;
import java.util.Objects;

/**
 * A host as TRADE names it: a host name together with one IP address of that host. A value:
 * immutable, serializable, comparable with {@link #equals}; safe for concurrent use.
 *
 * <p>Unlike {@link InetAddress}, it never resolves anything: the name and the address are kept as
 * given, so a value that travels to another machine means the same host there, and
 * {@link #toInetAddress()} needs no name service.
 */
public final class TRADEInetAddress implements Serializable {
  private static final long serialVersionUID = 1L;

  /** The host name. */
  private final String name;
  /** The IPv4 or IPv6 address: 4 or 16 bytes. */
  private final byte[] address;

  /**
   * The host {@code name} at {@code address}.
   *
   * @param name the host name; when null, the address's text is used as the name
   * @param address the host's address
   * @throws NullPointerException if {@code address} is null
   */
  public TRADEInetAddress(String name, InetAddress address) {
    Objects.requireNonNull(address, "address == null");
    this.address = address.getAddress();
    this.name = name != null ? name : address.getHostAddress();
  }

  /**
   * The host of {@code address}, named by the name it already holds (no lookup is made: an address
   * created from a literal has its text as name).
   *
   * @param address the host's address
   * @throws NullPointerException if {@code address} is null
   */
  public TRADEInetAddress(InetAddress address) {
    this(nameWithoutLookup(address), address);
  }

  private static String nameWithoutLookup(InetAddress address) {
    Objects.requireNonNull(address, "address == null");
    String text = address.toString(); // "name/ip", or "/ip" when it has no name: never a lookup
    int slash = text.indexOf('/');
    return slash > 0 ? text.substring(0, slash) : address.getHostAddress();
  }

  /**
   * A stream may hold anything: keep the invariants the constructors keep.
   *
   * @param in the stream
   * @throws IOException if it cannot be read, or holds no valid host
   * @throws ClassNotFoundException if it names a class not known here
   */
  private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
    in.defaultReadObject();
    if (name == null || address == null || address.length != 4 && address.length != 16) {
      throw new InvalidObjectException(
          "a TRADEInetAddress needs a name and 4 or 16 address bytes");
    }
  }

  /**
   * The host name.
   *
   * @return the name
   */
  public String getName() {
    return name;
  }

  /**
   * The IP address as text: {@code 192.168.1.7}, or the full form of an IPv6 address.
   *
   * @return the address
   */
  public String getAddress() {
    return toInetAddress().getHostAddress();
  }

  /**
   * This host as an {@link InetAddress} with this name and address; no name service is asked.
   *
   * @return the address
   */
  public InetAddress toInetAddress() {
    try {
      return InetAddress.getByAddress(name, address);
    } catch (UnknownHostException e) {
      throw new IllegalStateException("an address of " + address.length + " bytes", e); // 4 or 16
    }
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof TRADEInetAddress
        && ((TRADEInetAddress) o).name.equals(name)
        && Arrays.equals(((TRADEInetAddress) o).address, address);
  }

  @Override
  public int hashCode() {
    return name.hashCode() * 31 + Arrays.hashCode(address);
  }

  /** {@code name/address}, as {@link InetAddress#toString()} writes it. */
  @Override
  public String toString() {
    return name + "/" + getAddress();
  }
}
