package dev.trade;

import java.lang.annotation.Annotation;
import java.time.Duration;
import java.util.Collection;
import java.util.List;

/**
 * The JVM's default {@link TRADEContainer}, as static methods: the API TRADE users write against.
 *
 * <p>The default container is created on first use, from the configuration found by
 * {@link TRADEContainer.Builder#loadConfiguration()}, and lives as long as the JVM: it is not
 * closed at exit, so that components' own shutdown hooks can still deregister through it (hooks
 * run at the same time, and one that closed it would make theirs fail); its links end with the
 * process, which its peers notice at once. Every method is safe to call from any thread.
 *
 * <pre>{@code
 * TRADE.registerAllServices(new RobotArm(), "MyRobot");
 * for (TRADEServiceInfo s : TRADE.getAvailableServices(new TRADEServiceConstraints().inGroups("MyRobot"))) {
 *   if (s.serviceString.equals("openGripper(int)")) {
 *     s.call(void.class, 3);
 *   }
 * }
 * }</pre>
 */
public final class TRADE {
  private static final Object LOCK = new Object();
  private static volatile TRADEContainer defaultContainer;

  private TRADE() {}

  /**
   * The default container, created now if this is the first use.
   *
   * @throws IllegalArgumentException if the configuration is invalid (the message names the key);
   *     the next call tries again
   */
  public static TRADEContainer getDefaultContainer() {
    TRADEContainer c = defaultContainer;
    if (c == null) {
      synchronized (LOCK) {
        c = defaultContainer;
        if (c == null) {
          c = TRADEContainer.builder().loadConfiguration().build();
          defaultContainer = c;
        }
      }
    }
    return c;
  }

  static TRADEContainer defaultContainer() {
    return getDefaultContainer();
  }

  /** See {@link TRADEContainer#registerAllServices(Object, Collection)}. */
  public static Collection<TRADEServiceInfo> registerAllServices(Object provider, Collection<String> groups)
      throws TRADEException {
    return getDefaultContainer().registerAllServices(provider, groups);
  }

  /** See {@link TRADEContainer#registerAllServices(Object, String...)}. */
  public static Collection<TRADEServiceInfo> registerAllServices(Object provider, String... groups)
      throws TRADEException {
    return getDefaultContainer().registerAllServices(provider, groups);
  }

  /** See {@link TRADEContainer#register(Object, String)}. */
  public static Collection<TRADEServiceInfo> register(Object provider, String group) throws TRADEException {
    return getDefaultContainer().register(provider, group);
  }

  /** See {@link TRADEContainer#register(Object, Collection)}. */
  public static Collection<TRADEServiceInfo> register(Object provider, Collection<String> groups)
      throws TRADEException {
    return getDefaultContainer().register(provider, groups);
  }

  /** See {@link TRADEContainer#deregister(Object)}. */
  public static void deregister(Object provider) throws TRADEException {
    getDefaultContainer().deregister(provider);
  }

  /** See {@link TRADEContainer#getAvailableService(TRADEServiceConstraints)}. */
  public static TRADEServiceInfo getAvailableService(TRADEServiceConstraints constraints)
      throws TRADEException {
    return getDefaultContainer().getAvailableService(constraints);
  }

  /** See {@link TRADEContainer#getAvailableServices()}. */
  public static Collection<TRADEServiceInfo> getAvailableServices() {
    return getDefaultContainer().getAvailableServices();
  }

  /** See {@link TRADEContainer#getAvailableServices(TRADEServiceConstraints)}. */
  public static Collection<TRADEServiceInfo> getAvailableServices(TRADEServiceConstraints constraints) {
    return getDefaultContainer().getAvailableServices(constraints);
  }

  /** See {@link TRADEContainer#requestNotification(Object, String, Object, List, String)}. */
  public static void requestNotification(Object listener, String type, Object argument,
      List<TRADEServiceInfo> services, String callbackMethod) throws TRADEException {
    getDefaultContainer().requestNotification(listener, type, argument, services, callbackMethod);
  }

  /** See {@link TRADEContainer#requestNotification(String, Object, List, TRADEServiceInfo)}. */
  public static String requestNotification(String type, Object argument,
      List<TRADEServiceInfo> services, TRADEServiceInfo callback) throws TRADEException {
    return getDefaultContainer().requestNotification(type, argument, services, callback);
  }

  /** See {@link TRADEContainer#cancelNotification(Object, String, Object)}. */
  public static void cancelNotification(Object listener, String type, Object argument)
      throws TRADEException {
    getDefaultContainer().cancelNotification(listener, type, argument);
  }

  /** See {@link TRADEContainer#cancelNotification(String)}. */
  public static boolean cancelNotification(String id) throws TRADEException {
    return getDefaultContainer().cancelNotification(id);
  }

  /** See {@link TRADEContainer#registerNotificationNowOrWhenJoined}. */
  public static Collection<TRADEServiceInfo> registerNotificationNowOrWhenJoined(Object listener,
      TRADEServiceConstraints constraints, String callbackMethod) throws TRADEException {
    return getDefaultContainer().registerNotificationNowOrWhenJoined(listener, constraints,
        callbackMethod);
  }

  /** See {@link TRADEContainer#waitForService}. */
  public static TRADEServiceInfo waitForService(TRADEServiceConstraints constraints,
      Duration timeout) throws TRADEException {
    return getDefaultContainer().waitForService(constraints, timeout);
  }

  /** See {@link TRADEContainer#setDiscovery(boolean)}. */
  public static void setDiscovery(boolean on) {
    getDefaultContainer().setDiscovery(on);
  }

  /** See {@link TRADEContainer#setBroadcast(boolean)}. */
  public static void setBroadcast(boolean on) {
    getDefaultContainer().setBroadcast(on);
  }

  /** See {@link TRADEContainer#getAvailableServices(Class, TRADEServiceConstraints)}. */
  public static Collection<TRADEServiceInfo> getAvailableServices(
      Class<? extends Annotation> annotation, TRADEServiceConstraints constraints) {
    return getDefaultContainer().getAvailableServices(annotation, constraints);
  }
}
