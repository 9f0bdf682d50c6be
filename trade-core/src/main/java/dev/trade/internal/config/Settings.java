package dev.trade.internal.config;

import static java.util.Objects.requireNonNull;

import java.lang.System.Logger.Level;
import java.net.InetAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.StringJoiner;
import java.util.TreeSet;
import java.util.function.Function;

/**
 * The configuration of one TRADE container: every key of a {@code trade.properties} file, parsed,
 * validated and typed.
 *
 * <p>Instances are immutable and safe for concurrent use; {@link #with} and {@link #withAll}
 * return changed copies. Every key always has a value: a key that was not given, or was given
 * as empty text, has its default. Values are trimmed before they are parsed.
 *
 * <pre>{@code
 * Settings s = Settings.load();                       // file, class path or defaults
 * Settings t = s.with("CALLTIMEOUT", "5000");         // a copy with a 5 s call deadline
 * Duration deadline = t.callTimeout();
 * }</pre>
 *
 * <p>Keys are TRADE's upper-case names, matched case-sensitively. Each key is validated on its
 * own, so the order in which different keys are set never matters; relations between keys (such as
 * FAILURETIMEOUT being several HEARTBEATINTERVALs) are the concern of the code that uses them.
 * The key {@code RUNWEBSERVER}, which TRADE once read, is accepted and ignored. See
 * {@code docs/configuration.md} for every key.
 */
public final class Settings {
  /** System property naming a properties file; checked first by {@link #load()}. */
  public static final String PATH_PROPERTY = "trade.properties.path";
  /** Environment variable naming a properties file; checked second by {@link #load()}. */
  public static final String PATH_ENV = "TRADE_PROPERTIES_PATH";
  /** File in the working directory checked third, and class-path resource checked fourth. */
  public static final String RESOURCE = "trade.properties";

  private static final Settings DEFAULTS = new Settings(parsedDefaults());

  /** Never modified after construction, never handed out. */
  private final EnumMap<Key, Object> values;

  private Settings(EnumMap<Key, Object> values) {
    this.values = values;
  }

  /** The built-in defaults: networking off, everything in this JVM. */
  public static Settings defaults() {
    return DEFAULTS;
  }

  /**
   * The defaults with every entry of {@code properties} applied, including entries from its
   * defaults chain. Entries whose key or value is not a String are ignored, as
   * {@link Properties#stringPropertyNames()} does.
   *
   * @throws IllegalArgumentException for an unknown key or a bad value; with several problems,
   *     the one whose key sorts first is reported
   */
  public static Settings fromProperties(Properties properties) {
    return DEFAULTS.withAll(properties);
  }

  /**
   * Finds and loads the settings, using the first source that is set or present:
   *
   * <ol>
   *   <li>the file named by the system property {@value #PATH_PROPERTY};
   *   <li>the file named by the environment variable {@value #PATH_ENV};
   *   <li>the file {@value #RESOURCE} in the working directory, if there is one (as TRADE);
   *   <li>a {@value #RESOURCE} resource on the thread context class loader (or, when there is
   *       none, the loader of this class);
   *   <li>{@link #defaults()}.
   * </ol>
   *
   * <p>A path that is set (not blank) but names no readable file is an error; it does not fall
   * through to the next source, because silently running on defaults hides a typo.
   *
   * @throws IllegalArgumentException naming the source (and file) for a missing file, an unknown
   *     key or a bad value
   * @throws java.io.UncheckedIOException if an existing file cannot be read
   */
  public static Settings load() {
    ClassLoader loader = Thread.currentThread().getContextClassLoader();
    if (loader == null) {
      loader = Settings.class.getClassLoader();
    }
    return load(System::getProperty, System::getenv, Path.of(""), loader);
  }

  /** {@link #load()} with its sources injected, for tests. */
  static Settings load(
      Function<String, String> systemProperties,
      Function<String, String> environment,
      Path workingDirectory,
      ClassLoader loader) {
    return SettingsLoader.load(systemProperties, environment, workingDirectory, loader);
  }

  /**
   * Returns a copy with {@code key} set to {@code value} (trimmed; empty means the default).
   * A legacy key such as {@code RUNWEBSERVER} returns this instance unchanged.
   *
   * @throws IllegalArgumentException for an unknown key, suggesting the closest known one, or a
   *     bad value: "BROADCASTPORT=70000: expected a port 1..65535"
   */
  public Settings with(String key, String value) {
    requireNonNull(key, "key == null");
    requireNonNull(value, "value == null");
    if (Key.LEGACY.contains(key)) {
      ignoreLegacy(key);
      return this;
    }
    Key k = Key.named(key);
    EnumMap<Key, Object> copy = new EnumMap<>(values);
    copy.put(k, k.parse(value));
    return new Settings(copy);
  }

  /**
   * Returns a copy with every entry of {@code properties} applied on top of this instance; see
   * {@link #fromProperties} for which entries count and which error is reported.
   *
   * @throws IllegalArgumentException for an unknown key or a bad value
   */
  public Settings withAll(Properties properties) {
    requireNonNull(properties, "properties == null");
    EnumMap<Key, Object> copy = new EnumMap<>(values);
    // Sorted, so that a file with several mistakes always reports the same one first.
    for (String name : new TreeSet<>(properties.stringPropertyNames())) {
      if (Key.LEGACY.contains(name)) {
        ignoreLegacy(name);
        continue;
      }
      Key k = Key.named(name);
      copy.put(k, k.parse(properties.getProperty(name)));
    }
    return new Settings(copy);
  }

  /** CONTAINERNAME; the empty string means the container picks a name itself. */
  public String containerName() {
    return (String) values.get(Key.CONTAINERNAME);
  }

  /** STARTDISCOVERY: listen for other containers' multicast announcements. */
  public boolean startDiscovery() {
    return bool(Key.STARTDISCOVERY);
  }

  /** STARTBROADCAST: announce this container by multicast. */
  public boolean startBroadcast() {
    return bool(Key.STARTBROADCAST);
  }

  /** MCAST_ADDR: the multicast group for announcements; always a multicast address. */
  public InetAddress multicastAddress() {
    return (InetAddress) values.get(Key.MCAST_ADDR);
  }

  /** BROADCASTPORT: the UDP port of the multicast group, 1..65535. */
  public int broadcastPort() {
    return (Integer) values.get(Key.BROADCASTPORT);
  }

  /** BROADCASTINTERVAL: time between two announcements; positive. */
  public Duration broadcastInterval() {
    return duration(Key.BROADCASTINTERVAL);
  }

  /** DISCOVERYTIMEOUT: how long startup waits for announcements; zero means not at all. */
  public Duration discoveryTimeout() {
    return duration(Key.DISCOVERYTIMEOUT);
  }

  /**
   * CALLCONTAINERDISCOVERYTIMEOUT: how long a lookup waits for a container that is not known yet;
   * zero means not at all.
   */
  public Duration callContainerDiscoveryTimeout() {
    return duration(Key.CALLCONTAINERDISCOVERYTIMEOUT);
  }

  /** STARTACCEPTINGCONNECTIONS: listen on {@link #serverAddresses()} for other containers. */
  public boolean startAcceptingConnections() {
    return bool(Key.STARTACCEPTINGCONNECTIONS);
  }

  /** SERVERIPS: the addresses to listen on; port 0 means any free port. Unmodifiable. */
  public List<PeerAddress> serverAddresses() {
    return peers(Key.SERVERIPS);
  }

  /** CONNECTCONTAINERS: containers to connect to at startup; ports are 1..65535. Unmodifiable. */
  public List<PeerAddress> connectContainers() {
    return peers(Key.CONNECTCONTAINERS);
  }

  /** SCANFORSERVER: accepted for compatibility with TRADE files. */
  public boolean scanForServer() {
    return bool(Key.SCANFORSERVER);
  }

  /**
   * TIMEOUT_CLIENT_SOCKET: the connect timeout for a connection to another container, and the
   * longest its handshake may take.
   */
  public Duration clientSocketTimeout() {
    return duration(Key.TIMEOUT_CLIENT_SOCKET);
  }

  /** CALLCHECKTIME: how often a pending remote call checks that its provider is still there. */
  public Duration callCheckTime() {
    return duration(Key.CALLCHECKTIME);
  }

  /** USEENCRYPTION: encrypt traffic between containers. */
  public boolean useEncryption() {
    return bool(Key.USEENCRYPTION);
  }

  /** CREDENTIALS: what this container presents to others. Never log it; use toString(). */
  public String credentials() {
    return (String) values.get(Key.CREDENTIALS);
  }

  /**
   * Whether CREDENTIALS is TRADE's published default while this container reaches beyond its own
   * host (subnet discovery, or an address to listen on or connect to that is not loopback): then
   * anyone who can reach it can join the system.
   */
  public boolean defaultCredentialsBeyondThisHost() {
    if (!credentials().equals(DEFAULTS.credentials())) {
      return false;
    }
    if ((startDiscovery() || startBroadcast()) && discoveryRange() == DiscoveryRange.SUBNET) {
      return true;
    }
    for (List<PeerAddress> list : List.of(serverAddresses(), connectContainers())) {
      for (PeerAddress a : list) {
        if (!isLoopback(a.host())) {
          return true;
        }
      }
    }
    return false;
  }

  /** Loopback by its text alone: settings never resolve host names. */
  private static boolean isLoopback(String host) {
    InetAddress literal = Addresses.literal(host);
    return literal != null ? literal.isLoopbackAddress() : host.equalsIgnoreCase("localhost");
  }

  /** TRADESYSID: containers only join others of the same system id. */
  public String tradeSysId() {
    return (String) values.get(Key.TRADESYSID);
  }

  /** COPYDATAFORLOCALINVOKES: copy arguments and results of calls within this container. */
  public boolean copyDataForLocalInvokes() {
    return bool(Key.COPYDATAFORLOCALINVOKES);
  }

  /** CALLTIMEOUT: the default deadline of every remote call; positive. */
  public Duration callTimeout() {
    return duration(Key.CALLTIMEOUT);
  }

  /** HEARTBEATINTERVAL: time between heartbeats to each connected container; positive. */
  public Duration heartbeatInterval() {
    return duration(Key.HEARTBEATINTERVAL);
  }

  /** FAILURETIMEOUT: a container silent for this long is declared gone; positive. */
  public Duration failureTimeout() {
    return duration(Key.FAILURETIMEOUT);
  }

  /** DISCOVERYRANGE: how far discovery packets travel. */
  public DiscoveryRange discoveryRange() {
    return (DiscoveryRange) values.get(Key.DISCOVERYRANGE);
  }

  /**
   * DISCOVERYINTERFACES, else TRADE's NETWORKINTERFACE: interface names for SUBNET discovery;
   * empty means all. Unmodifiable.
   */
  @SuppressWarnings("unchecked") // both keys always parse to a List<String>
  public List<String> discoveryInterfaces() {
    List<String> ours = (List<String>) values.get(Key.DISCOVERYINTERFACES);
    return ours.isEmpty() ? (List<String>) values.get(Key.NETWORKINTERFACE) : ours;
  }

  /**
   * KEEPTRYING: whether the CONNECTCONTAINERS addresses are dialled again after a failed attempt or
   * a lost link (true), or dialled once at start only (false).
   */
  public boolean keepTrying() {
    return (Boolean) values.get(Key.KEEPTRYING);
  }

  /**
   * DISCOVERYCLOCKSKEW: how far the clock in another host's announcement may be from this host's,
   * either way; zero turns the check off (replays are then refused by sequence numbers alone).
   */
  public Duration discoveryClockSkew() {
    return duration(Key.DISCOVERYCLOCKSKEW);
  }

  /** SERIALIZATIONALLOWLIST: class patterns added to the built-in allow-list. Unmodifiable. */
  @SuppressWarnings("unchecked") // Key.SERIALIZATIONALLOWLIST always parses to a List<String>
  public List<String> serializationAllowList() {
    return (List<String>) values.get(Key.SERIALIZATIONALLOWLIST);
  }

  /** MAXFRAMESIZE: the largest frame, in bytes, sent or accepted between containers. */
  public int maxFrameSize() {
    return (Integer) values.get(Key.MAXFRAMESIZE);
  }

  /** PRINCIPALSFILE: the access file (principals, roles, secrets, rules); empty for none. */
  public String principalsFile() {
    return (String) values.get(Key.PRINCIPALSFILE);
  }

  /**
   * PRINCIPAL: the credentials ({@code <principal>:<secret>}) this container proves on the calls it
   * makes; empty for anonymous. Never log it; use toString().
   */
  public String principal() {
    return (String) values.get(Key.PRINCIPAL);
  }

  /** PROVIDERCLASSES: the classes a remote administrator may start providers of. Unmodifiable. */
  @SuppressWarnings("unchecked") // Key.PROVIDERCLASSES always parses to a List<String>
  public List<String> providerClasses() {
    return (List<String>) values.get(Key.PROVIDERCLASSES);
  }

  /** HOOKTIMEOUT: the longest a synchronous hook may delay a call; positive. */
  public Duration hookTimeout() {
    return duration(Key.HOOKTIMEOUT);
  }

  /** HOOKSYSTEMSERVICES: whether hooks may wrap this container's services of the reserved group. */
  public boolean hookSystemServices() {
    return bool(Key.HOOKSYSTEMSERVICES);
  }

  /** CALLLOG: the file the call log writes, started with the container; empty: no call log. */
  public String callLog() {
    return (String) values.get(Key.CALLLOG);
  }

  /** CALLLOGGROUPS: the groups whose services the call log covers; empty: every service. */
  public List<String> callLogGroups() {
    List<String> groups = new ArrayList<>();
    for (String g : ((String) values.get(Key.CALLLOGGROUPS)).split(",")) {
      if (!g.isBlank()) {
        groups.add(g.trim());
      }
    }
    return List.copyOf(groups);
  }

  /** CALLLOGMAXBYTES: the size at which the call log file is rotated. */
  public int callLogMaxBytes() {
    return (Integer) values.get(Key.CALLLOGMAXBYTES);
  }

  /**
   * Every key with its canonical text, in canonical order (TRADE's keys, then ours). The texts
   * load back into equal settings. CREDENTIALS appears in clear: do not log this map.
   *
   * @return an unmodifiable map
   */
  public Map<String, String> asMap() {
    Map<String, String> map = new LinkedHashMap<>();
    values.forEach((k, v) -> map.put(k.name(), k.format(v)));
    return Collections.unmodifiableMap(map);
  }

  /** Settings are equal when every key has an equal value. */
  @Override
  public boolean equals(Object o) {
    return o instanceof Settings && values.equals(((Settings) o).values);
  }

  @Override
  public int hashCode() {
    return values.hashCode();
  }

  /** {@code Settings{CONTAINERNAME=, ..., CREDENTIALS=****, ...}}: safe to log (PRINCIPAL too). */
  @Override
  public String toString() {
    StringJoiner joiner = new StringJoiner(", ", "Settings{", "}");
    values.forEach((k, v) -> joiner.add(k + "=" + (k.isSecret() ? "****" : k.format(v))));
    return joiner.toString();
  }

  private boolean bool(Key key) {
    return (Boolean) values.get(key);
  }

  private Duration duration(Key key) {
    return (Duration) values.get(key);
  }

  @SuppressWarnings("unchecked") // SERVERIPS and CONNECTCONTAINERS parse to List<PeerAddress>
  private List<PeerAddress> peers(Key key) {
    return (List<PeerAddress>) values.get(key);
  }

  private static void ignoreLegacy(String key) {
    // Looked up here, not held in a static field: the first logger of a JVM costs tens of ms
    // (the logging backend is found and set up), and most settings never need one.
    System.getLogger(Settings.class.getName())
        .log(Level.DEBUG, "ignoring {0}: TRADE no longer reads this key", key);
  }

  private static EnumMap<Key, Object> parsedDefaults() {
    EnumMap<Key, Object> map = new EnumMap<>(Key.class);
    for (Key k : Key.values()) {
      map.put(k, k.parse("")); // empty text means the default
    }
    return map;
  }
}
