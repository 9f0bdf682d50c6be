package dev.trade.testing;

import dev.trade.TRADEContainer;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Builds containers linked over loopback and closes them after each test, the last built first.
 * A <em>hub</em> accepts connections on loopback; a <em>spoke</em> connects to the hubs it is
 * given. Register it as a field:
 *
 * <pre>{@code
 * @RegisterExtension final Hubs net = new Hubs();
 *
 * TRADEContainer hub = net.hub("hub");
 * TRADEContainer spoke = net.spoke("spoke", hub);
 * }</pre>
 *
 * <p>Not safe for concurrent use: a test builds its containers on one thread.
 */
public final class Hubs implements AfterEachCallback {
  private final List<TRADEContainer> built = new ArrayList<>();

  /** A container named {@code name} that accepts connections on loopback. */
  public TRADEContainer hub(String name) {
    return keep(hubBuilder(name).build());
  }

  /** A container named {@code name} that keeps a link to each of {@code hubs}. */
  public TRADEContainer spoke(String name, TRADEContainer... hubs) {
    return keep(spokeBuilder(name, hubs).build());
  }

  /** The builder of {@link #hub}, for tests that add properties; pass its result to {@link #keep}. */
  public static TRADEContainer.Builder hubBuilder(String name) {
    return TRADEContainer.builder().name(name).property("STARTACCEPTINGCONNECTIONS", "true")
        .property("SERVERIPS", Loopback.ANY_PORT);
  }

  /** The builder of {@link #spoke}; pass its result to {@link #keep}. */
  public static TRADEContainer.Builder spokeBuilder(String name, TRADEContainer... hubs) {
    return TRADEContainer.builder().name(name).property("CONNECTCONTAINERS", addresses(hubs));
  }

  /** CONNECTCONTAINERS for {@code hubs}: the first address each listens on. */
  public static String addresses(TRADEContainer... hubs) {
    List<String> all = new ArrayList<>();
    for (TRADEContainer h : hubs) {
      all.add(h.getServerAddresses().get(0));
    }
    return String.join(",", all);
  }

  /** Closes {@code c} after the test, before the containers built earlier. */
  public TRADEContainer keep(TRADEContainer c) {
    built.add(c);
    return c;
  }

  @Override
  public void afterEach(ExtensionContext context) {
    for (int i = built.size() - 1; i >= 0; i--) {
      built.get(i).close();
    }
    built.clear();
  }
}
