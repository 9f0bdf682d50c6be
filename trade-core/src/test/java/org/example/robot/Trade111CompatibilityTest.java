package org.example.robot;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADE;
import dev.trade.TRADEContainer;
import dev.trade.TRADEEffect;
import dev.trade.TRADEEffectType;
import dev.trade.TRADEEffectsContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEInetAddress;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.lang.annotation.Annotation;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.net.InetAddress;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** What TRADE 1.1.1 code observes of service infos, constraints and TRADE's other types. */
class Trade111CompatibilityTest {
  private final TRADEContainer trade = TRADEContainer.builder().name("compat").build();

  @AfterEach
  void close() {
    trade.close();
  }

  @Retention(RetentionPolicy.RUNTIME)
  @interface Speed {}

  public static class Gripper {
    @TRADEService
    @TRADEEffect(effect = "open(gripper)", type = TRADEEffectType.SUCCESS)
    @TRADEEffect(effect = "stuck(gripper)", type = TRADEEffectType.FAILURE, observable = "touching")
    public boolean openGripper(@Speed int speed, double[] xs, long l)
        throws IOException, InterruptedException {
      return speed > 0 && xs.length == 1 && l == 7L;
    }

    @TRADEService
    public String[] names(String[][] table) {
      return table[0];
    }
  }

  private TRADEServiceInfo openGripper() throws TRADEException {
    trade.registerAllServices(new Gripper(), "MyRobot");
    return trade.getAvailableService(new TRADEServiceConstraints().name("openGripper"));
  }

  @Test
  void typesAreNamedAsTrade111NamesThem() throws TRADEException {
    TRADEServiceInfo s = openGripper();
    assertEquals("openGripper(int,[D,long)", s.serviceString);
    assertArrayEquals(new String[] {"java.lang.Integer", "[D", "java.lang.Long"},
        s.serviceParameterTypeNames);
    assertArrayEquals(new Class<?>[] {Integer.class, double[].class, Long.class},
        s.getServiceParameterTypes());
    assertEquals("boolean", s.serviceReturnTypeName);
    assertSame(boolean.class, s.getServiceReturnType());
    assertArrayEquals(new String[] {"java.io.IOException", "java.lang.InterruptedException"},
        s.exceptionTypeNames);
    TRADEServiceInfo names = trade.getAvailableService(new TRADEServiceConstraints().name("names"));
    assertEquals("names([[Ljava.lang.String;)", names.serviceString);
    assertArrayEquals(new String[] {"[[Ljava.lang.String;"}, names.serviceParameterTypeNames);
    assertEquals("[Ljava.lang.String;", names.serviceReturnTypeName);
    assertArrayEquals(new String[0], names.exceptionTypeNames);
  }

  @Test
  void argTypesAcceptPrimitiveAndBoxedClasses() throws TRADEException {
    TRADEServiceInfo s = openGripper();
    for (Class<?>[] types : List.of(new Class<?>[] {int.class, double[].class, long.class},
        new Class<?>[] {Integer.class, double[].class, Long.class}, s.getServiceParameterTypes())) {
      assertEquals(s, trade.getAvailableService(new TRADEServiceConstraints().argTypes(types)));
    }
    assertTrue(s.call(boolean.class, 3, new double[] {0.5}, 7L));
  }

  @Test
  void annotationsAreListsAndParametersHaveTheirOwn() throws TRADEException {
    TRADEServiceInfo s = openGripper();
    List<Annotation> annotations = s.getAnnotations();
    assertTrue(annotations.stream().anyMatch(a -> a instanceof TRADEService), annotations.toString());
    TRADEEffectsContainer effects = annotations.stream()
        .filter(a -> a instanceof TRADEEffectsContainer).map(a -> (TRADEEffectsContainer) a)
        .findFirst().orElseThrow();
    assertEquals(2, effects.value().length);
    assertEquals(TRADEEffectType.FAILURE, effects.value()[1].type());
    assertArrayEquals(new String[] {"touching"}, effects.value()[1].observable());
    assertArrayEquals(new String[0], effects.value()[0].sideEffect());
    assertThrows(UnsupportedOperationException.class, () -> annotations.add(effects));
    List<List<Annotation>> parameters = s.getParameterAnnotations();
    assertEquals(3, parameters.size());
    assertInstanceOf(Speed.class, parameters.get(0).get(0));
    assertEquals(List.of(), parameters.get(1));
    assertEquals(List.of(s), List.copyOf(
        trade.getAvailableServices(TRADEEffectsContainer.class, new TRADEServiceConstraints())));
    Class<?> notAnAnnotation = String.class;
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> trade.getAvailableServices(notAnAnnotation, null));
    assertTrue(e.getMessage().contains("java.lang.String is not an annotation type"), e.getMessage());
  }

  @Test
  void serviceInfosCloneAndSerialize() throws Exception {
    TRADEServiceInfo s = openGripper();
    TRADEServiceInfo copy = s.clone();
    assertNotSame(s, copy);
    assertEquals(s, copy);
    assertNotSame(s.serviceParameterTypeNames, copy.serviceParameterTypeNames);
    assertTrue(copy.call(boolean.class, 1, new double[] {1}, 7L));

    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
      out.writeObject(s);
    }
    TRADEServiceInfo back;
    try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
      back = (TRADEServiceInfo) in.readObject();
    }
    assertEquals(s, back);
    assertEquals(s.serviceString, back.serviceString);
    assertArrayEquals(s.exceptionTypeNames, back.exceptionTypeNames);
  }

  @Test
  void hostConstraintsAndEquality() throws TRADEException {
    TRADEServiceInfo s = openGripper();
    String host = trade.getHost();
    TRADEServiceConstraints open = new TRADEServiceConstraints().name("openGripper");
    assertEquals(s, trade.getAvailableService(open.onLocalhost()));
    assertEquals(s, trade.getAvailableService(new TRADEServiceConstraints().name("openGripper")
        .onHost(host)));
    assertTrue(trade.getAvailableServices(new TRADEServiceConstraints().notOnLocalhost()).isEmpty());
    assertTrue(trade.getAvailableServices(new TRADEServiceConstraints().notOnHost("elsewhere", host))
        .isEmpty());

    TRADEServiceConstraints a = new TRADEServiceConstraints().name("x").argTypes(int.class)
        .inGroups("g").notOnHost("h").onLocalhost();
    TRADEServiceConstraints b = new TRADEServiceConstraints().onLocalhost().notOnHost("h")
        .inGroups("g").argTypes(int.class).name("x");
    assertEquals(a, b);
    assertEquals(a.hashCode(), b.hashCode());
    assertNotEquals(a, b.notOnLocalhost());
    assertNotEquals(a, new TRADEServiceConstraints().name("x").argTypes(long.class).inGroups("g")
        .notOnHost("h").onLocalhost());
    assertTrue(b.toString().contains("notOnLocalhost"), b.toString());
    TRADEServiceConstraints sub = new TRADEServiceConstraints() {};
    assertNotEquals(new TRADEServiceConstraints(), sub); // another class: TRADE's is not final
  }

  @Test
  void effectTypesParseIgnoringCase() {
    assertSame(TRADEEffectType.SUCCESS, TRADEEffectType.fromString("success"));
    assertSame(TRADEEffectType.NONPERF, TRADEEffectType.fromString(" NonPerf "));
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> TRADEEffectType.fromString("sometimes"));
    assertTrue(e.getMessage().contains("always, success, failure, nonperf"), e.getMessage());
    assertThrows(IllegalArgumentException.class, () -> TRADEEffectType.fromString(null));
  }

  @Test
  void inetAddressesKeepNameAndAddressWithoutLookups() throws Exception {
    TRADEInetAddress a = new TRADEInetAddress("robot1", InetAddress.getByAddress(new byte[] {10, 0, 0, 7}));
    assertEquals("robot1", a.getName());
    assertEquals("10.0.0.7", a.getAddress());
    assertEquals(InetAddress.getByAddress("robot1", new byte[] {10, 0, 0, 7}), a.toInetAddress());
    assertEquals("robot1", a.toInetAddress().getHostName());
    TRADEInetAddress literal = new TRADEInetAddress(InetAddress.getByName("127.0.0.1"));
    assertEquals("127.0.0.1", literal.getName());
    ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
      out.writeObject(a);
    }
    try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
      assertEquals(a, in.readObject());
    }
    assertFalse(a.equals(literal));
  }

  @Test
  void lastModifiedIsAnIsoDate() {
    assertTrue(TRADE.lastmodified.matches("\\d{4}-\\d{2}-\\d{2}"), TRADE.lastmodified);
  }
}
