package org.example.compat;

import dev.trade.TRADE;
import dev.trade.TRADEEffect;
import dev.trade.TRADEEffectType;
import dev.trade.TRADEEffectsContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInetAddress;
import dev.trade.TRADENotAuthorizedException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.InputStream;
import java.io.Serializable;
import java.lang.annotation.Annotation;
import java.net.InetAddress;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.UUID;
import java.util.Map;

/**
 * User code written against TRADE 1.1.1's public API (docs/api.md, "Differences from TRADE 1.1.1";
 * the list of members comes from TRADE 1.1.1's jar signatures), compiled with the tests and never
 * run: a change that breaks source compatibility with TRADE fails the build here.
 *
 * <p>Every call that TRADE declares with {@code throws TRADEException} sits in its own
 * {@code try/catch (TRADEException)}, which does not compile if the method stops declaring it;
 * every call that TRADE declares without it sits outside any {@code try}, in methods without a
 * {@code throws} clause, which does not compile if it starts declaring it.
 *
 * <p>Members still missing are kept at the end, commented out, each with the issue that adds it.
 */
@SuppressWarnings({"unused", "UnusedAssignment"})
public class Trade111Api {

  /** A provider in DIARC's style: interface methods carry the annotations. */
  public interface Gripper {
    @TRADEService
    @TRADEEffect(effect = {"open(gripper)"}, type = TRADEEffectType.SUCCESS)
    @TRADEEffect(effect = {"stuck(gripper)"}, type = TRADEEffectType.FAILURE,
        observable = {"touching(gripper)"}, sideEffect = {"moved(arm)"})
    boolean openGripper(int speed, double[] xs, long l) throws TRADEException;

    @TRADEService
    void joined(TRADEServiceInfo service);
  }

  /** TRADE's constraints class is not final: user code may extend it. */
  static final class MyGroupConstraints extends TRADEServiceConstraints {
    MyGroupConstraints(String group) {
      inGroups(group);
    }
  }

  String lastModified = TRADE.lastmodified;

  /** The static API. */
  void trade(Object provider, Object listener) {
    Collection<TRADEServiceInfo> mine = null;
    try {
      mine = TRADE.registerAllServices(provider, "MonitoringGroup");
    } catch (TRADEException e) {
      report(e);
    }
    try {
      mine = TRADE.registerAllServices(provider, (String) null);
    } catch (TRADEException e) {
      report(e);
    }
    try {
      mine = TRADE.registerAllServices(provider, new ArrayList<String>());
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.deregister(provider);
    } catch (TRADEException e) {
      report(e);
    }

    TRADEServiceConstraints c = new TRADEServiceConstraints();
    Collection<TRADEServiceInfo> all = TRADE.getAvailableServices();
    Collection<TRADEServiceInfo> some = TRADE.getAvailableServices(c);
    Class<?> annotation = TRADEService.class;
    Collection<TRADEServiceInfo> annotated = TRADE.getAvailableServices(annotation, c);
    try {
      TRADEServiceInfo one = TRADE.getAvailableService(c);
    } catch (TRADEException e) {
      report(e);
    }

    // Notifications, in the forms DIARC uses (see the end for TRADE 1.1.1's exact types).
    try {
      TRADE.requestNotification(listener, "joined", c, null, "joined");
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.requestNotification(listener, "left", c, null, "left");
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.cancelNotification(listener, "joined", null);
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.registerNotificationNowOrWhenJoined(listener, c, "joined");
    } catch (TRADEException e) {
      report(e);
    }
  }

  /** Hooks (#37), and the TRADE paper's string form of them. */
  void hooks(TRADEServiceInfo wrapper, TRADEServiceInfo target, String serviceName,
      String[] serviceArgsClasses, TRADEServiceConstraints constr) {
    try {
      TRADE.beforeService(wrapper, target);
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.afterService(wrapper, target);
    } catch (TRADEException e) {
      report(e);
    }
    try {
      TRADE.afterService("addObservedOutput", new String[] {Object[].class.getName()},
          new TRADEServiceConstraints(), serviceName, serviceArgsClasses, constr);
    } catch (TRADEException e) {
      report(e);
    }
  }

  /** Constraints: every builder method, chained and as separate statements. */
  void constraints() {
    TRADEServiceConstraints c = new TRADEServiceConstraints()
        .inGroups("agent:hugo", "location")
        .notInGroups("Sim")
        .name("openGripper")
        .argTypes(int.class, double[].class, Long.class)
        .returnType(boolean.class)
        .onLocalhost()
        .notOnLocalhost()
        .onHost("robot1")
        .notOnHost("robot2", "robot3");
    c.argTypes();
    c.name("closeGripper");
    boolean same = c.equals(new MyGroupConstraints("agent:hugo"));
    int hash = c.hashCode();
    String text = c.toString();
  }

  /** Service infos: fields, calls, reflection on types and annotations. */
  void serviceInfo(TRADEServiceInfo s) {
    String serviceString = s.serviceString;
    String serviceName = s.serviceName;
    String[] typeNames = s.serviceParameterTypeNames;
    String[] names = s.serviceParameterNames;
    String returnTypeName = s.serviceReturnTypeName;
    String[] exceptionTypeNames = s.exceptionTypeNames;
    try {
      boolean opened = s.call(boolean.class, 3, new double[] {0.5}, 7L);
      s.call(void.class);
      Object any = s.call(Object.class, new ArrayList<>().toArray());
    } catch (TRADEException e) {
      report(e);
    }
    Collection<String> groups = s.getGroups();
    List<Annotation> annotations = s.getAnnotations();
    List<List<Annotation>> parameterAnnotations = s.getParameterAnnotations();
    Class<?>[] parameterTypes = s.getServiceParameterTypes();
    Class<?> returnType = s.getServiceReturnType();
    String text = s.toString();
    Serializable serializable = s;
    Cloneable cloneable = s;
    TRADEServiceInfo copy = s.clone();
  }

  /** The other types. */
  void otherTypes(Gripper gripper) throws Exception {
    try {
      gripper.openGripper(3, new double[0], 1L);
    } catch (TRADENotAuthorizedException e) {
      report(e);
    } catch (TRADEException e) {
      report(e);
    }
    Exception asException = new TRADENotAuthorizedException("no");
    TRADEEffectType type = TRADEEffectType.fromString("success");
    TRADEEffectType[] all = {TRADEEffectType.ALWAYS, TRADEEffectType.SUCCESS,
        TRADEEffectType.FAILURE, TRADEEffectType.NONPERF};
    TRADEEffect[] effects = Gripper.class.getMethod("openGripper", int.class, double[].class,
        long.class).getAnnotationsByType(TRADEEffect.class);
    TRADEEffectsContainer container = Gripper.class.getMethod("openGripper", int.class,
        double[].class, long.class).getAnnotation(TRADEEffectsContainer.class);
    String[] effect = effects[0].effect();
    TRADEEffectType when = effects[0].type();
    String[] observable = effects[0].observable();
    String[] sideEffect = effects[0].sideEffect();
    TRADEInetAddress host = new TRADEInetAddress(InetAddress.getLoopbackAddress());
    String name = host.getName();
    String address = host.getAddress();
    InetAddress inet = host.toInetAddress();
    Serializable serializable = host;
  }

  /** Locks over sets of services. */
  void locks(TRADEServiceInfo s) {
    UUID any = TRADE.lockServicesContainOne(List.of("arm"));
    UUID every = TRADE.lockServicesContainAll(List.of("arm", "head"));
    try {
      TRADE.releaseLock(any);
    } catch (TRADEException e) {
      report(e);
    }
    try {
      boolean b = s.call(every, boolean.class, 3);
    } catch (TRADEException e) {
      report(e);
    }
  }

  /** The middleware's own operations, with credentials (#39). */
  void middleware(String credentials, InputStream inputStream, TRADEServiceInfo s) {
    try { TRADE.reset(credentials); } catch (TRADEException e) { report(e); }
    try { TRADE.loadConfig(credentials, inputStream); } catch (TRADEException e) { report(e); }
    try { TRADE.accessToTRADEServices(credentials, true); } catch (TRADEException e) { report(e); }
    try { TRADE.findInterfaces(credentials); } catch (TRADEException e) { report(e); }
    try { TRADE.setEncryption(credentials, true); } catch (TRADEException e) { report(e); }
    try { TRADE.shutdownTRADE(credentials); } catch (TRADEException e) { report(e); }
    try { TRADE.setBroadcast(credentials, true); } catch (TRADEException e) { report(e); }
    try { TRADE.setDiscovery(credentials, true); } catch (TRADEException e) { report(e); }
    try { Map<String, Collection<String>> graph = TRADE.getTRADEContainerGraph(credentials); }
    catch (TRADEException e) { report(e); }
    try { TRADE.startListenForConnections(credentials, "127.0.0.1", 10002); }
    catch (TRADEException e) { report(e); }
    try { TRADE.stopListenForConnections(credentials); } catch (TRADEException e) { report(e); }
    try { TRADE.setServiceGroups(s, List.of("a")); } catch (TRADEException e) { report(e); }
    try { TRADE.addServiceGroups(s, List.of("a")); } catch (TRADEException e) { report(e); }
    try { TRADE.removeServiceGroups(s, List.of("a")); } catch (TRADEException e) { report(e); }
    try { TRADE.resetServiceGroups(s); } catch (TRADEException e) { report(e); }
  }

  private static void report(Exception e) {
    e.printStackTrace();
  }

  /** Notifications with TRADE 1.1.1's exact parameter and return types. */
  void notifications(Object listener, Object argument, List<TRADEServiceInfo> services,
      TRADEServiceConstraints c) {
    try { TRADE.requestNotification(listener, "once", argument, services, "done"); }
    catch (TRADEException e) { report(e); }
    try { TRADE.cancelNotification(listener, "every", argument); }
    catch (TRADEException e) { report(e); }
    try { Collection<TRADEServiceInfo> now =
        TRADE.registerNotificationNowOrWhenJoined(listener, c, "joined"); }
    catch (TRADEException e) { report(e); }
  }

}
