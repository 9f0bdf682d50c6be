package dev.trade.internal.call;

import dev.trade.TRADEException;
import java.util.List;

/**
 * An immutable chain of {@link CallLink}s ending in a terminal link that does not call
 * {@code next}. With no links before the terminal, a call costs one virtual call. Thread-safe.
 */
public final class CallChain {
  private static final CallLink.Next END = call -> {
    throw new IllegalStateException("the terminal link of a chain must not call next");
  };

  private final CallLink[] links;

  /** The chain {@code links..., terminal}. */
  public CallChain(List<CallLink> links, CallLink terminal) {
    this.links = new CallLink[links.size() + 1];
    for (int i = 0; i < links.size(); i++) {
      this.links[i] = links.get(i);
    }
    this.links[links.size()] = terminal;
  }

  public Object call(Invocation call) throws TRADEException {
    return links.length == 1 ? links[0].proceed(call, END) : new Step(0).proceed(call);
  }

  private final class Step implements CallLink.Next {
    private final int index;
    private boolean used;

    Step(int index) {
      this.index = index;
    }

    @Override
    public Object proceed(Invocation call) throws TRADEException {
      if (used) {
        throw new IllegalStateException(links[index - 1].getClass().getName()
            + " called next.proceed() more than once");
      }
      used = true;
      return links[index].proceed(call, index + 1 < links.length ? new Step(index + 1) : END);
    }
  }
}
