package dev.trade.internal.config;

/**
 * The kinds of setting value: how each kind's text is parsed and formatted, by the functions of
 * {@link Values}.
 *
 * <p>A switch rather than a parser object per key: the settings are the first thing a container
 * builds, and each method reference would be a class generated at run time in every JVM that
 * starts one (see docs/benchmarks-log.md, "Start → callable").
 */
enum ValueType {
  TEXT, CONTAINER_NAME, SYSTEM_ID, BOOL, MULTICAST, PORT, MILLIS, MILLIS_OR_ZERO, LISTEN_ADDRESSES,
  CONNECT_ADDRESSES, DISCOVERY_RANGE, INTERFACES, ALLOW_LIST, FRAME_SIZE;

  /** See {@link Key#parse}: trimmed non-empty text in, an immutable value or IAE out. */
  Object parse(String s) {
    switch (this) {
      case TEXT: return Values.text(s);
      case CONTAINER_NAME: return Values.containerName(s);
      case SYSTEM_ID: return Values.systemId(s);
      case BOOL: return Values.bool(s);
      case MULTICAST: return Values.multicast(s);
      case PORT: return Values.integer(s, "port", 1, 65535);
      case MILLIS: return Values.millis(s, 1);
      case MILLIS_OR_ZERO: return Values.millis(s, 0);
      case LISTEN_ADDRESSES: return Values.listenAddresses(s);
      case CONNECT_ADDRESSES: return Values.connectAddresses(s);
      case DISCOVERY_RANGE: return Values.discoveryRange(s);
      case INTERFACES: return Values.interfaces(s);
      case ALLOW_LIST: return Values.allowList(s);
      case FRAME_SIZE: return Values.integer(s, "size in bytes", 1024, Integer.MAX_VALUE - 8);
      default: throw new AssertionError(this);
    }
  }

  /** The canonical text of {@code value}, which {@link #parse} accepts again. */
  String format(Object value) {
    switch (this) {
      case MULTICAST: return Values.hostAddress(value);
      case MILLIS:
      case MILLIS_OR_ZERO: return Values.millisText(value);
      case LISTEN_ADDRESSES:
      case CONNECT_ADDRESSES:
      case INTERFACES: return Values.joined(value, ",");
      case ALLOW_LIST: return Values.joined(value, ";");
      default: return String.valueOf(value);
    }
  }
}
