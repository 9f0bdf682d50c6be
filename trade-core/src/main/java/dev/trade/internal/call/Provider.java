package dev.trade.internal.call;

import dev.trade.TRADEException;
import dev.trade.internal.registry.LocalService;

/**
 * The providing side of a container as networking sees it: the services registered here and the
 * host chain that every call to them passes, whichever way it came. Safe for concurrent use.
 */
public interface Provider {
  /** The service registered here with this id, or null if there is none (any longer). */
  LocalService local(long serviceId);

  /** Runs {@code call} through this container's host chain. */
  Object invoke(Invocation call) throws TRADEException;
}
