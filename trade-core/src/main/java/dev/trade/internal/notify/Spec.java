package dev.trade.internal.notify;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.internal.registry.Query;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.system.ConstraintsForm;
import java.time.Instant;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;

/**
 * A notification request, checked: every way it can be wrong is found here, at request time, so
 * that nothing is scheduled for a bad one. Immutable (the argument array is not shared).
 *
 * @param kind the type
 * @param timing when it is due (null for joined and left)
 * @param query the services of interest of joined and left (null for the others)
 * @param service {@code services[0]}: the service called or the condition; null when none
 * @param serviceArgs the arguments of {@code service}
 * @param callback the callback service
 * @param shape what the callback takes
 * @param requester who asked (a container's name), for the list and the log
 */
record Spec(Kind kind, Timing timing, Query query, ServiceDescriptor service, Object[] serviceArgs,
    ServiceDescriptor callback, Shape shape, String requester) {

  /**
   * Checks a request made at {@code nowNanos} (scheduler time) and {@code nowInstant}.
   *
   * @param argument the type's argument: constraints (or their {@link ConstraintsForm}) for joined
   *     and left; the service's arguments
   *     for once; a time for the others, alone or as the first element of an array or list whose
   *     other elements are the service's arguments
   * @param queries turns joined and left's argument into a query; null when it is of another kind
   * @throws TRADEBadArgumentsException naming what is wrong and what is expected
   */
  static Spec parse(String type, Object argument, List<ServiceDescriptor> services,
      ServiceDescriptor callback, String requester, Function<Object, Query> queries, long nowNanos,
      Instant nowInstant) throws TRADEBadArgumentsException {
    Kind kind = Kind.parse(type);
    if (callback == null) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' needs a callback service");
    }
    List<ServiceDescriptor> given = services == null ? List.of() : services;
    if (!kind.takesService() && !given.isEmpty()) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' takes no services (its argument"
          + " is the constraints); got " + given.size());
    }
    if (given.size() > 1) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' takes one service (services[0]);"
          + " got " + given.size());
    }
    if (kind.needsService() && given.isEmpty()) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' needs services[0]: "
          + (kind.isCondition() ? "the condition, a service returning boolean" : "the service to call"));
    }
    ServiceDescriptor service = given.isEmpty() ? null : given.get(0);
    if (kind.isCondition() && !isBoolean(service.returnTypeName())) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' needs a condition returning boolean;"
          + " " + service.signature() + " returns " + service.returnTypeName());
    }
    if (kind == Kind.JOINED || kind == Kind.LEFT) {
      Query q = queries.apply(ConstraintsForm.isForm(argument) ? ConstraintsForm.decode(argument)
          : argument);
      if (q == null) {
        throw new TRADEBadArgumentsException("'" + kind.label() + "' needs constraints (a map as"
            + " docs/protocol.md describes, or a TRADEServiceConstraints) or null as its argument;"
            + " got " + argument.getClass().getName());
      }
      return new Spec(kind, null, q, null, new Object[0], callback,
          Shape.of(kind, null, callback), requester);
    }
    Object time = null;
    Object[] args;
    if (kind == Kind.ONCE) {
      args = elements(argument);
    } else {
      Object[] all = argument instanceof Object[] || argument instanceof List
          ? elements(argument) : new Object[] {argument};
      if (all.length == 0) {
        throw new TRADEBadArgumentsException("'" + kind.label() + "' needs a time argument; got an"
            + " empty list");
      }
      time = all[0];
      args = Arrays.copyOfRange(all, 1, all.length);
    }
    if (service == null && args.length > 0) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "' got " + args.length
          + " service arguments but no service");
    }
    if (service != null && args.length != service.parameterTypeNames().size()) {
      throw new TRADEBadArgumentsException("'" + kind.label() + "': " + service.signature() + " takes "
          + service.parameterTypeNames().size() + " arguments; the request gives " + args.length);
    }
    Timing timing = Timing.of(kind, time, nowNanos, nowInstant);
    return new Spec(kind, timing, null, service, args, callback, Shape.of(kind, service, callback),
        requester);
  }

  private static Object[] elements(Object argument) {
    if (argument == null) {
      return new Object[0];
    }
    if (argument instanceof Object[]) {
      return ((Object[]) argument).clone();
    }
    if (argument instanceof List) {
      return ((List<?>) argument).toArray();
    }
    return new Object[] {argument};
  }

  private static boolean isBoolean(String typeName) {
    return "boolean".equals(typeName) || Boolean.class.getName().equals(typeName);
  }
}
