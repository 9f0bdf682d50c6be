package dev.trade;

import dev.trade.internal.call.ServiceCaller;
import dev.trade.internal.registry.ServiceDescriptor;
import dev.trade.internal.registry.Types;
import java.io.ObjectStreamException;
import java.io.Serializable;
import java.lang.annotation.Annotation;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.List;
import java.util.LinkedHashSet;
import java.util.Objects;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;

/**
 * A handle to one provided service: what it is (name, parameters, return type, groups,
 * annotations), where it lives (container and host), and a way to call it.
 *
 * <p>A service info is a value. It may be stored, passed as a service argument to another
 * container and compared after it travelled: {@link #equals} and {@link #hashCode} compare the
 * identity of the provided service (its container's incarnation and its service number), not the
 * Java object. It stays callable while the service is registered; afterwards every call fails with
 * {@link TRADEServiceUnavailableException}.
 *
 * <p>The public fields keep TRADE's names and report types as TRADE 1.1.1 does: for
 * {@code boolean openGripper(int speed, double[] xs, long l)}, {@link #serviceString} is
 * {@code openGripper(int,[D,long)}, {@link #serviceParameterTypeNames} is
 * {@code [java.lang.Integer, [D, java.lang.Long]} (primitives boxed, so that a caller can convert
 * arguments by these names), and {@link #serviceReturnTypeName} is {@code boolean} (as declared).
 * Each info has arrays of its own; a caller that changes them changes only its own copy.
 * Immutable apart from that, and safe for concurrent use.
 */
public final class TRADEServiceInfo implements Serializable, Cloneable {
  private static final long serialVersionUID = 1L;

  /** The method name, e.g. {@code openGripper}. */
  public final String serviceName;
  /**
   * {@code name(T1,T2)} with each declared parameter type's {@link Class#getName()}:
   * {@code openGripper(int)}, {@code openGripper(int,[D,long)}.
   */
  public final String serviceString;
  /** The parameter names (real names when the provider was compiled with {@code -parameters}). */
  public final String[] serviceParameterNames;
  /**
   * {@link Class#getName()} of each parameter type, a primitive type replaced by its box:
   * {@code java.lang.Integer} for {@code int}, {@code [D} for {@code double[]}.
   */
  public final String[] serviceParameterTypeNames;
  /** {@link Class#getName()} of the declared return type: {@code boolean}, {@code void}, {@code [D}. */
  public final String serviceReturnTypeName;
  /** {@link Class#getName()} of each exception type the service method declares, in order. */
  public final String[] exceptionTypeNames;

  private final transient ServiceDescriptor descriptor;
  private final transient ServiceCaller caller;
  private final transient long timeoutNanos;
  private final transient boolean waitForLock;

  TRADEServiceInfo(ServiceDescriptor descriptor, ServiceCaller caller) {
    this(descriptor, caller, 0, false);
  }

  private TRADEServiceInfo(ServiceDescriptor descriptor, ServiceCaller caller, long timeoutNanos,
      boolean waitForLock) {
    this.descriptor = Objects.requireNonNull(descriptor, "descriptor == null");
    this.caller = Objects.requireNonNull(caller, "caller == null");
    this.timeoutNanos = timeoutNanos;
    this.waitForLock = waitForLock;
    this.serviceName = descriptor.name();
    List<String> types = descriptor.parameterTypeNames();
    String[] binary = new String[types.size()];
    String[] boxed = new String[types.size()];
    for (int i = 0; i < binary.length; i++) {
      binary[i] = Types.binaryName(types.get(i));
      boxed[i] = Types.boxedBinaryName(types.get(i));
    }
    this.serviceString = descriptor.name() + "(" + String.join(",", binary) + ")";
    this.serviceParameterNames = descriptor.parameterNames().toArray(new String[0]);
    this.serviceParameterTypeNames = boxed;
    this.serviceReturnTypeName = Types.binaryName(descriptor.returnTypeName());
    this.exceptionTypeNames = descriptor.exceptionTypeNames().toArray(new String[0]);
  }

  /**
   * Calls the service with {@code args} and returns its result.
   *
   * <p>{@code returnType} may be the declared return type, a supertype of it ({@code Object.class}
   * takes anything), a subtype (checked on the returned value), a primitive class
   * ({@code boolean.class} returns a {@code Boolean} usable as a {@code boolean}) or
   * {@code void.class} (returns null whatever the service returns). The arguments are checked
   * against the signature before the service runs. Passing a single array to a service whose only
   * parameter is an array passes that array as the one argument.
   *
   * <pre>{@code
   * boolean opened = info.call(boolean.class, 3);
   * }</pre>
   *
   * @param <T> the type of the result
   * @param returnType the class of the result (see above); not null
   * @param args the arguments, in the order of the service's parameters
   * @return the service's result as {@code returnType}; null for {@code void.class}
   * @throws TRADEBadArgumentsException the arguments or {@code returnType} do not fit; nothing ran
   * @throws TRADEInvocationException the service threw; the cause is what it threw
   * @throws TRADEServiceUnavailableException the service is gone (deregistered, container left)
   * @throws TRADETimeoutException a remote reply did not arrive before the deadline
   * @throws TRADESerializationException an argument or the result could not be copied or travel
   */
  public <T> T call(Class<T> returnType, Object... args) throws TRADEException {
    Objects.requireNonNull(returnType, "returnType == null");
    return waitForLock ? caller.callUnderLock(descriptor, null, true, returnType, args, timeoutNanos)
        : caller.call(descriptor, returnType, args, timeoutNanos);
  }

  /**
   * Calls the service under lock {@code lock} (TRADE 1.1.1's form): the call carries the lock's id
   * and its fencing token for this service, and the service's container lets it run only while
   * that lock holds the service. Calls under a lock are made from the container that took it.
   *
   * <pre>{@code
   * UUID lock = TRADE.lockServicesContainAll(List.of("head"));
   * if (lock != null) {
   *   try {
   *     head.call(lock, void.class, 30.0);
   *   } finally {
   *     TRADE.releaseLock(lock);
   *   }
   * }
   * }</pre>
   *
   * @param <T> the type of the result
   * @param lock the lock's id, as {@code lockServicesContainAll} or {@link TRADELock#getId()}
   *     gave it; null makes this an ordinary {@link #call(Class, Object...)}
   * @param returnType the class of the result (as for {@link #call(Class, Object...)}); not null
   * @param args the arguments, in the order of the service's parameters
   * @return the service's result as {@code returnType}; null for {@code void.class}
   * @throws TRADELockedException the lock does not hold the service (any more: released, its
   *     lease ended, it left, or the lock was not taken from this container); the service did not
   *     run
   * @throws TRADEException as {@link #call(Class, Object...)} otherwise
   */
  public <T> T call(UUID lock, Class<T> returnType, Object... args) throws TRADEException {
    Objects.requireNonNull(returnType, "returnType == null");
    return lock == null && !waitForLock ? caller.call(descriptor, returnType, args, timeoutNanos)
        : caller.callUnderLock(descriptor, lock, waitForLock, returnType, args, timeoutNanos);
  }

  /**
   * This service info, whose synchronous calls wait while another lock holds the service, until
   * it is free or the call's deadline passes (then {@link TRADELockedException}); without it, a
   * call to a service locked by another lock fails at once. Asynchronous calls do not wait. Equal
   * to this one.
   *
   * @return a service info for the same service whose calls wait for locks
   */
  public TRADEServiceInfo waitingForLock() {
    return new TRADEServiceInfo(descriptor, caller, timeoutNanos, true);
  }

  /**
   * Calls the service without blocking: the future completes with its result as {@code call}
   * would return it, or exceptionally with the {@link TRADEException} {@code call} would throw
   * ({@code get()} wraps it in an {@code ExecutionException}, {@code join()} in a
   * {@code CompletionException}).
   *
   * <p>A remote call holds no thread while its reply is outstanding: the connection's reading
   * thread completes it, and the reply is decoded on a pooled thread of the container, where
   * dependent stages without an executor of their own run too. A local call runs on such a pooled
   * thread. The call's deadline is this info's (see {@link #withTimeout}); when it passes, the
   * future fails with {@link TRADETimeoutException}. A remote call that finds its connection
   * congested fails at once with {@link TRADEServiceUnavailableException} rather than wait.
   *
   * @param <T> the result's type
   * @param returnType the result's class ({@code void.class} or {@code Void.class} for none)
   * @param args the arguments, as for {@link #call(Class, Object...)}
   * @return the future result
   * @throws NullPointerException if {@code returnType} is null
   */
  public <T> CompletableFuture<T> callAsync(Class<T> returnType, Object... args) {
    Objects.requireNonNull(returnType, "returnType == null");
    return caller.callAsync(descriptor, returnType, args, timeoutNanos);
  }

  /**
   * This service info with another deadline for its calls (the default comes from the
   * {@code CALLTIMEOUT} setting). Equal to this one.
   *
   * @param timeout how long a call waits for a remote reply; positive
   * @return a service info for the same service with that deadline
   * @throws IllegalArgumentException if {@code timeout} is zero or negative
   */
  public TRADEServiceInfo withTimeout(Duration timeout) {
    if (timeout.isNegative() || timeout.isZero()) {
      throw new IllegalArgumentException("timeout must be positive: " + timeout);
    }
    long nanos;
    try {
      nanos = timeout.toNanos();
    } catch (ArithmeticException tooLong) {
      nanos = Long.MAX_VALUE / 4; // centuries: as good as no deadline, without overflowing it
    }
    return new TRADEServiceInfo(descriptor, caller, nanos, waitForLock);
  }

  /**
   * The declared parameter types, a primitive type replaced by its box ({@code Integer.class} for
   * {@code int}), as TRADE reports them; a new array on each call.
   *
   * @return a new array of the parameter types, in order
   * @throws TypeNotPresentException if a parameter type is not known in this JVM
   */
  public Class<?>[] getServiceParameterTypes() {
    Class<?>[] types = new Class<?>[serviceParameterTypeNames.length];
    for (int i = 0; i < types.length; i++) {
      types[i] = Types.box(resolve(descriptor.parameterTypeNames().get(i)));
    }
    return types;
  }

  /**
   * The declared return type.
   *
   * @return the return type, {@code void.class} for none
   * @throws TypeNotPresentException if the type is not known in this JVM
   */
  public Class<?> getServiceReturnType() {
    return resolve(descriptor.returnTypeName());
  }

  /**
   * The groups the service was registered in.
   *
   * @return the groups in registration order; empty for none
   */
  public Collection<String> getGroups() {
    return descriptor.groups();
  }

  /**
   * The annotations on the service method and the declarations it overrides, one per type, as an
   * unmodifiable list. For a service of another container: those whose annotation type this JVM
   * knows and does not refuse (see docs/protocol.md, "What the receiver enforces").
   *
   * @return the annotations; maybe none
   */
  public List<Annotation> getAnnotations() {
    return descriptor.annotations();
  }

  /**
   * The annotations of each parameter, one unmodifiable list per parameter (empty for a parameter
   * without any), gathered like {@link #getAnnotations()}.
   *
   * @return one list per parameter
   */
  public List<List<Annotation>> getParameterAnnotations() {
    return descriptor.parameterAnnotations();
  }

  /**
   * The providing container's incarnation.
   *
   * @return its id, new each time a container starts
   */
  public String getContainerId() {
    return descriptor.containerId();
  }

  /**
   * The providing container's name.
   *
   * @return the {@code CONTAINERNAME} of the container that provides the service
   */
  public String getContainerName() {
    return descriptor.containerName();
  }

  /**
   * The host of the providing container.
   *
   * @return the host name or address the container announced
   */
  public String getHost() {
    return descriptor.host();
  }

  /**
   * How many links a call crosses from the container this info was obtained from to the providing
   * one: 0 for its own services, 1 for a directly connected container, more through forwarding;
   * -1 when the service is not known there (any more).
   *
   * @return the number of links, or -1
   */
  public int getDistance() {
    return caller.distance(descriptor);
  }

  /**
   * Whether the service is provided by the container this info was obtained from.
   *
   * @return true for a service of that container
   */
  public boolean isLocal() {
    return descriptor.containerId().equals(caller.containerId());
  }

  ServiceDescriptor descriptor() {
    return descriptor;
  }

  /**
   * A copy of this info: equal to it, bound to the same container, with the same deadline, and with
   * arrays of its own.
   */
  @Override
  public TRADEServiceInfo clone() {
    return new TRADEServiceInfo(descriptor, caller, timeoutNanos, waitForLock);
  }

  private static Class<?> resolve(String typeName) {
    ClassLoader context = Thread.currentThread().getContextClassLoader();
    Class<?> c = context == null ? null : Types.resolve(typeName, context);
    if (c == null) {
      c = Types.resolve(typeName, TRADEServiceInfo.class.getClassLoader());
    }
    if (c == null) {
      throw new TypeNotPresentException(typeName, null);
    }
    return c;
  }

  @Override
  public boolean equals(Object o) {
    return o instanceof TRADEServiceInfo && descriptor.sameService(((TRADEServiceInfo) o).descriptor);
  }

  @Override
  public int hashCode() {
    return descriptor.containerId().hashCode() * 31 + Long.hashCode(descriptor.serviceId());
  }

  /** {@code serviceString [groups] @ container}, for logs. */
  @Override
  public String toString() {
    return serviceString + (descriptor.groups().isEmpty() ? "" : " " + descriptor.groups())
        + " @ " + descriptor.containerName();
  }

  /**
   * Java serialization (for users that keep infos in Serializable objects) goes through a plain
   * form and binds the result to the default container; annotations are not carried.
   *
   * @return the plain form
   * @throws ObjectStreamException never
   */
  private Object writeReplace() throws ObjectStreamException {
    return new SerialForm(this);
  }

  private static final class SerialForm implements Serializable {
    private static final long serialVersionUID = 1L;
    private final String containerId;
    private final String containerName;
    private final String host;
    private final long serviceId;
    private final String name;
    private final ArrayList<String> parameterNames;
    private final ArrayList<String> parameterTypeNames;
    private final String returnTypeName;
    private final ArrayList<String> groups;
    private final String genericReturnTypeName;
    private final ArrayList<String> exceptionTypeNames;

    SerialForm(TRADEServiceInfo info) {
      ServiceDescriptor d = info.descriptor;
      containerId = d.containerId();
      containerName = d.containerName();
      host = d.host();
      serviceId = d.serviceId();
      name = d.name();
      parameterNames = new ArrayList<>(d.parameterNames());
      parameterTypeNames = new ArrayList<>(d.parameterTypeNames());
      returnTypeName = d.returnTypeName();
      groups = new ArrayList<>(d.groups());
      genericReturnTypeName = d.genericReturnTypeName();
      exceptionTypeNames = new ArrayList<>(d.exceptionTypeNames());
    }

    private Object readResolve() throws ObjectStreamException {
      ServiceDescriptor d = new ServiceDescriptor(containerId, containerName, host, serviceId, name,
          parameterNames, parameterTypeNames, returnTypeName, new LinkedHashSet<>(groups), List.of(),
          genericReturnTypeName == null ? returnTypeName : genericReturnTypeName,
          exceptionTypeNames == null ? List.of() : exceptionTypeNames,
          Collections.nCopies(parameterNames.size(), List.of()));
      return TRADE.defaultContainer().bind(d);
    }
  }
}
