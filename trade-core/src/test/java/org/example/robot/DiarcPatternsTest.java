package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.TRADEServiceNotFoundException;
import dev.trade.TRADEServiceUnavailableException;
import java.lang.annotation.Annotation;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The usage patterns of DIARC, TRADE's largest user (see TRADE-API.md). */
class DiarcPatternsTest {
  private final TRADEContainer trade = TRADEContainer.builder().name("diarc").build();
  private final BeliefComponent beliefs = new BeliefComponent();

  @AfterEach
  void close() {
    trade.close();
  }

  @Test
  void annotationOnInterfaceMethodsOnlyMakesServices() throws TRADEException {
    Collection<TRADEServiceInfo> mine = trade.registerAllServices(beliefs, new ArrayList<>());
    Set<String> names = new HashSet<>();
    mine.forEach(s -> names.add(s.serviceString));
    // Arrays as Class.getName() names them, as TRADE 1.1.1 writes its serviceString.
    assertEquals(Set.of("queryBelief(org.example.robot.Term)", "joinOnGoal(long)", "getKBName()",
        "registerForNotification(org.example.robot.Term,dev.trade.TRADEServiceInfo)",
        "countAll([Ljava.lang.Object;)"), names);
  }

  @Test
  void argTypesWithNoArgumentsMeansExactlyZeroParameters() throws TRADEException {
    trade.registerAllServices(beliefs, "agent:hugo:agent");
    trade.registerAllServices(new Object() {
      @TRADEService
      public String getKBName(String which) {
        return which;
      }
    });
    TRADEServiceConstraints c = new TRADEServiceConstraints().name("getKBName").argTypes();
    assertEquals(1, trade.getAvailableServices(c).size());
    assertEquals("beliefs", trade.getAvailableService(c).call(String.class));
    assertEquals(2, trade.getAvailableServices(new TRADEServiceConstraints().name("getKBName")).size());
  }

  @Test
  void boxedMatchesPrimitiveAndSubtypesMatchDeclaredTypes() throws TRADEException {
    trade.registerAllServices(beliefs);
    TRADEServiceInfo join = trade.getAvailableService(
        new TRADEServiceConstraints().name("joinOnGoal").argTypes(Long.class));
    assertTrue(join.call(boolean.class, 42L));
    TRADEServiceInfo query = trade.getAvailableService(
        new TRADEServiceConstraints().name("queryBelief").argTypes(Term.Predicate.class));
    assertEquals(List.of(new Term.Predicate("on")), query.call(List.class, new Term.Predicate("on")));
    assertThrows(TRADEServiceNotFoundException.class, () -> trade.getAvailableService(
        new TRADEServiceConstraints().name("queryBelief").argTypes(String.class)));
  }

  @Test
  void constraintsAreMutableLastWriteWinsAndChainInAnyOrder() throws TRADEException {
    trade.registerAllServices(beliefs, "agent:hugo:agent");
    TRADEServiceConstraints c = new TRADEServiceConstraints();
    c.name("queryBelief"); // return value discarded, as PyTRADE does
    c.argTypes(Term.class);
    c.name("joinOnGoal").argTypes(long.class);
    assertEquals("joinOnGoal(long)", trade.getAvailableService(c).serviceString);
    TRADEServiceInfo viaGroups = trade.getAvailableService(new TRADEServiceConstraints()
        .inGroups("agent:hugo:agent").name("getKBName").argTypes());
    assertEquals("getKBName()", viaGroups.serviceString);
    assertEquals("java.lang.String", viaGroups.serviceReturnTypeName);
  }

  @Test
  void returnTypeAndNotInGroupsNarrowTheLookup() throws TRADEException {
    trade.registerAllServices(beliefs, "kb");
    trade.registerAllServices(new RobotArm(), "arm");
    assertEquals(List.of("joinOnGoal(long)", "openGripper(int)"), strings(trade.getAvailableServices(
        new TRADEServiceConstraints().returnType(boolean.class))));
    assertEquals(List.of("openGripper(int)"), strings(trade.getAvailableServices(
        new TRADEServiceConstraints().returnType(Boolean.class).notInGroups("kb"))));
    assertEquals(List.of("queryBelief(org.example.robot.Term)"), strings(trade.getAvailableServices(
        new TRADEServiceConstraints().returnType(List.class))));
    assertEquals(List.of("closeGripper()", "registerForNotification(org.example.robot.Term,"
        + "dev.trade.TRADEServiceInfo)"), strings(trade.getAvailableServices(
        new TRADEServiceConstraints().returnType(void.class))));
  }

  @Test
  void objectArrayAsVarargsAndParameterNamesAreReal() throws TRADEException {
    trade.registerAllServices(beliefs);
    TRADEServiceInfo join = trade.getAvailableService(new TRADEServiceConstraints().name("joinOnGoal"));
    List<Object> argList = List.of(42L);
    assertTrue((Boolean) join.call(Object.class, argList.toArray()));
    assertArrayEquals(new String[] {"goalId"}, join.serviceParameterNames);
    // Boxed, as TRADE 1.1.1 reports parameter types (DIARC converts arguments by them).
    assertArrayEquals(new Class<?>[] {Long.class}, join.getServiceParameterTypes());
    assertEquals(boolean.class, join.getServiceReturnType());
    TRADEServiceInfo count = trade.getAvailableService(new TRADEServiceConstraints().name("countAll"));
    assertEquals(3, count.call(int.class, new Object[] {"a", "b", "c"}));
    assertEquals(2, count.call(int.class, (Object) new String[] {"a", "b"}));
  }

  @Test
  void userAnnotationsTravelWithTheServiceInfo() throws TRADEException {
    trade.registerAllServices(beliefs);
    TRADEServiceInfo query = trade.getAvailableService(new TRADEServiceConstraints().name("queryBelief"));
    List<Class<?>> types = new ArrayList<>();
    for (Annotation a : query.getAnnotations()) {
      types.add(a.annotationType());
    }
    assertTrue(types.containsAll(List.of(TRADEService.class, Action.class)), types.toString());
    Collection<TRADEServiceInfo> actions = trade.getAvailableServices(Action.class, new TRADEServiceConstraints());
    assertEquals(List.of("queryBelief(org.example.robot.Term)"), strings(actions));
  }

  @Test
  void serviceInfosAreValuesUsableAsCallbacksAndSetKeys() throws TRADEException {
    trade.registerAllServices(beliefs);
    List<Term> received = new ArrayList<>();
    trade.registerAllServices(new Object() {
      @TRADEService
      public void onBelief(Term t) {
        received.add(t);
      }
    });
    TRADEServiceInfo callback = trade.getAvailableService(new TRADEServiceConstraints().name("onBelief"));
    trade.getAvailableService(new TRADEServiceConstraints().name("registerForNotification")
        .argTypes(Term.class, TRADEServiceInfo.class)).call(void.class, new Term("x"), callback);
    TRADEServiceInfo again = trade.getAvailableService(new TRADEServiceConstraints().name("onBelief"));
    assertNotSame(callback, again);
    assertEquals(callback, again);
    assertEquals(callback.hashCode(), again.hashCode());
    assertTrue(beliefs.callbacks.contains(again));
    beliefs.notifyAll(new Term("y"));
    assertEquals(List.of(new Term("y")), received);
  }

  @Test
  void deregisteredServiceFailsWithTheMessageExistingCodeMatches() throws TRADEException {
    trade.registerAllServices(beliefs);
    TRADEServiceInfo kb = trade.getAvailableService(new TRADEServiceConstraints().name("getKBName"));
    trade.deregister(beliefs);
    TRADEServiceUnavailableException e =
        assertThrows(TRADEServiceUnavailableException.class, () -> kb.call(String.class));
    assertTrue(e.getMessage().startsWith("Service not available any longer"), e.getMessage());
    assertTrue(trade.getAvailableServices(new TRADEServiceConstraints().name("getKBName")).isEmpty());
    assertFalse(kb.isLocal() && trade.getAvailableServices().contains(kb));
  }

  @Test
  void groupsNullEmptyAndBlankMeanNoGroup() throws TRADEException {
    assertTrue(only(trade.registerAllServices(new RobotArm(), (String) null)).isEmpty());
    assertTrue(only(trade.registerAllServices(new RobotArm(), "")).isEmpty());
    assertTrue(only(trade.registerAllServices(new RobotArm(), (Collection<String>) null)).isEmpty());
    assertTrue(only(trade.registerAllServices(new RobotArm())).isEmpty());
    assertEquals(List.of("a", "b"), List.copyOf(only(trade.registerAllServices(new RobotArm(),
        Arrays.asList("a", null, "b", "a")))));
  }

  @Test
  void unknownServiceInfoTypeIsReportedNotGuessed() throws TRADEException {
    trade.registerAllServices(beliefs);
    TRADEServiceInfo s = trade.getAvailableService(new TRADEServiceConstraints().name("queryBelief"));
    assertInstanceOf(Class.class, s.getServiceParameterTypes()[0]);
    assertEquals(Term.class, s.getServiceParameterTypes()[0]);
  }

  private static Collection<String> only(Collection<TRADEServiceInfo> infos) {
    return infos.iterator().next().getGroups();
  }

  private static List<String> strings(Collection<TRADEServiceInfo> infos) {
    List<String> result = new ArrayList<>();
    infos.forEach(i -> result.add(i.serviceString));
    result.sort(null);
    return result;
  }
}
