package dev.trade.internal.registry;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADERegistrationException;
import dev.trade.TRADEService;
import java.lang.invoke.MethodHandle;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;

/** Finds and prepares callback services (a listener's {@code @TRADEService} method). Stateless. */
public final class Callbacks {
  private Callbacks() {}

  /**
   * The invoker ({@code (Object target, Object[] args) Object}) of {@code listener}'s public
   * {@code @TRADEService} method {@code name} that takes exactly one {@code argType}.
   *
   * @throws TRADEBadArgumentsException naming the listener class and method when there is none
   */
  public static MethodHandle find(Object listener, String name, Class<?> argType)
      throws TRADEBadArgumentsException {
    Class<?> type = listener.getClass();
    List<String> candidates = new ArrayList<>();
    try {
      for (Method m : ServiceScanner.serviceMethods(type)) {
        if (!m.getName().equals(name)) {
          continue;
        }
        candidates.add(m.toGenericString());
        if (m.getParameterCount() == 1 && m.getParameterTypes()[0].isAssignableFrom(argType)) {
          return ServiceScanner.prepareInvoker(type, m);
        }
      }
    } catch (TRADERegistrationException e) {
      throw new TRADEBadArgumentsException(e.getMessage(), e);
    }
    boolean exists = false;
    for (Method m : type.getMethods()) {
      exists |= m.getName().equals(name) && !Modifier.isStatic(m.getModifiers());
    }
    String hint = candidates.isEmpty()
        ? (exists ? "it must carry @" + TRADEService.class.getSimpleName() + " (callbacks are services)"
            : "there is no public method of that name")
        : "it must take exactly one " + argType.getName() + "; found " + candidates;
    throw new TRADEBadArgumentsException("Callback " + type.getName() + "." + name + "("
        + argType.getSimpleName() + ") not usable: " + hint);
  }
}
