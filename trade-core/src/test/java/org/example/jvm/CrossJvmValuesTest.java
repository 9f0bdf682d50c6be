package org.example.jvm;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceInfo;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.atomic.AtomicInteger;
import org.example.jvm.RemoteTypes.Checkpoint;
import org.example.jvm.RemoteTypes.Gripper;
import org.example.jvm.RemoteTypes.Marked;
import org.example.jvm.RemoteTypes.Marker;
import org.example.jvm.RemoteTypes.Plan;
import org.example.jvm.RemoteTypes.Pose;
import org.example.jvm.RemoteTypes.Token;
import org.example.jvm.RemoteTypes.Waypoint;
import org.junit.jupiter.api.Test;

/**
 * Every kind of value the codec knows travels from this JVM to a {@link ProviderMain} JVM and back,
 * through real sockets on loopback: same values, same classes, same enum constants, service infos
 * that still call and compare equal. Exceptions, and classes not known or not allowed on one side:
 * {@link CrossJvmExceptionsAndAllowListTest}.
 */
class CrossJvmValuesTest extends ProviderFixture {
  private String typeOnProvider(Object value) throws TRADEException {
    return service("typeOf").call(String.class, new Object[] {value});
  }

  /** Equal after the round trip, of the same class, and of that class on the provider too. */
  private void assertTravels(Object value) throws TRADEException {
    Object back = echo(value);
    assertEquals(value, back);
    if (value != null) {
      assertSame(value.getClass(), back.getClass(), "class of " + value);
      assertEquals(value.getClass().getName(), typeOnProvider(value));
    }
  }

  @Test
  void scalarsAndJdkValuesKeepTheirValueAndClass() throws TRADEException {
    assertNull(echo(null));
    assertEquals("null", typeOnProvider(null));
    for (Object v : List.of(true, false, (byte) -128, (short) 300, 7, Integer.MIN_VALUE,
        Long.MAX_VALUE, 1.5f, -0.0f, Float.NaN, 2.25, Double.NEGATIVE_INFINITY, 'q', '\uFFFF', "",
        "grüße ☃ \uD83E\uDD16", "x".repeat(100_000), new BigInteger("-123456789012345678901234567890"),
        new BigDecimal("3.14159265358979323846"), UUID.randomUUID(), Instant.ofEpochSecond(1, 999),
        Duration.ofMillis(-1500), Pose.class, int.class)) {
      assertTravels(v);
    }
  }

  @Test
  void typedPrimitiveParametersAndResults() throws TRADEException {
    assertFalse(service("not").call(boolean.class, true));
    assertEquals((byte) 128, service("negateByte").call(byte.class, (byte) -128));
    assertEquals((short) -300, service("negateShort").call(short.class, (short) 300));
    assertEquals(-7, service("negateInt").call(int.class, 7));
    assertEquals(Long.MIN_VALUE + 1, service("negateLong").call(long.class, Long.MAX_VALUE));
    assertEquals(0.75f, service("halveFloat").call(float.class, 1.5f));
    assertEquals(-0.0, service("halveDouble").call(double.class, -0.0));
    assertEquals('b', service("nextChar").call(char.class, 'a'));
    assertEquals("ROBOT ☃", service("upper").call(String.class, "robot ☃"));
    assertNull(service("upper").call(String.class, (Object) null));
    // Widening as in Java: an int argument for a long parameter.
    assertEquals(-5L, service("negateLong").call(long.class, 5));
  }

  @Test
  void primitiveArrays() throws TRADEException {
    List<Object> arrays = List.of(new byte[] {1, -2, 3}, new boolean[] {true, false, true},
        new short[] {-1, 2}, new char[] {'a', '\u20AC'}, new int[] {0, -5, Integer.MAX_VALUE},
        new long[] {Long.MIN_VALUE, 3}, new float[] {1.5f, Float.NaN}, new double[] {-2.5, 1e300},
        new int[0], new int[][] {{1, 2}, {}, null});
    for (Object a : arrays) {
      Object back = echo(a);
      assertSame(a.getClass(), back.getClass());
      assertNotSame(a, back);
      assertTrue(Arrays.deepEquals(new Object[] {a}, new Object[] {back}), a.getClass().getName());
    }
    byte[] data = "0123456789".getBytes(UTF_8);
    assertArrayEquals("9876543210".getBytes(UTF_8),
        service("reverseBytes").call(byte[].class, (Object) data));
  }

  @Test
  void objectArraysKeepTheirComponentType() throws TRADEException {
    List<Object[]> arrays = List.of(new String[] {"a", null, "c"}, new Integer[] {1, null},
        new Object[] {1, "two", 3.0, null, List.of(4)}, new Pose[] {new Pose(1, 2, 3, "map")},
        new Gripper[] {Gripper.OPEN, Gripper.JAMMED}, new String[][] {{"a"}, {}}, new Number[] {1, 2L},
        new CharSequence[] {"cs"}, new Object[0]);
    for (Object[] a : arrays) {
      Object back = echo(a);
      assertSame(a.getClass(), back.getClass());
      assertArrayEquals(a, (Object[]) back);
      assertEquals(a.getClass().getName(), typeOnProvider(a));
    }
    String[] reversed = service("reverseStrings").call(String[].class, (Object) new String[] {"x", "y"});
    assertArrayEquals(new String[] {"y", "x"}, reversed);
    Pose[] poses = service("poses").call(Pose[].class, 3);
    assertSame(Pose[].class, poses.getClass());
    assertEquals(new Pose(2, -2, 0.2, "map"), poses[2]);
  }

  @Test
  void listsSetsAndMaps() throws TRADEException {
    List<Object> list = Arrays.asList(1, "two", null, 3.0, List.of(), new Pose(0, 0, 0, "x"));
    assertEquals(list, echo(list));
    assertEquals("java.util.ArrayList", typeOnProvider(List.of(1)));

    Set<Object> set = new LinkedHashSet<>(List.of("z", "a", 5, Gripper.CLOSED));
    Object setBack = echo(set);
    assertEquals(set, setBack);
    assertEquals(new ArrayList<>(set), new ArrayList<>((Set<?>) setBack), "set order");

    Map<Object, Object> map = new LinkedHashMap<>();
    map.put(1, "int key");
    map.put(new Pose(1, 2, 3, "key"), List.of("record key"));
    map.put(Gripper.OPEN, Map.of("nested", new int[0].length));
    map.put(null, "null key");
    map.put("null value", null);
    Object mapBack = echo(map);
    assertEquals(map, mapBack);
    assertEquals(new ArrayList<>(map.keySet()), new ArrayList<>(((Map<?, ?>) mapBack).keySet()));

    // Sorted and enum collections arrive as the codec's general kinds, with equal contents.
    TreeMap<String, Integer> sorted = new TreeMap<>(Map.of("b", 2, "a", 1));
    assertEquals(sorted, echo(sorted));
    assertEquals(EnumSet.of(Gripper.OPEN, Gripper.JAMMED), echo(EnumSet.of(Gripper.OPEN, Gripper.JAMMED)));
    EnumMap<Gripper, String> byGrip = new EnumMap<>(Map.of(Gripper.CLOSED, "closed"));
    assertEquals(byGrip, echo(byGrip));

    List<Map<String, List<Pose>>> nested = List.of(Map.of("route", List.of(new Pose(1, 1, 1, "a"))));
    assertEquals(nested, echo(nested));
  }

  @Test
  void enumsArriveAsTheSameConstant() throws TRADEException {
    for (Gripper g : Gripper.values()) {
      assertSame(g, echo(g));
    }
    // The constant with a body is an instance of its own subclass, there as here.
    assertEquals(Gripper.JAMMED.getClass().getName(), typeOnProvider(Gripper.JAMMED));
    assertSame(Gripper.CLOSED, service("toggle").call(Gripper.class, Gripper.OPEN));
  }

  @Test
  void recordsAreEqualAfterTheTrip() throws TRADEException {
    Pose p = new Pose(1.5, -2, Math.PI, "map");
    assertTravels(p);
    assertEquals(new Pose(4, -2, Math.PI, "map"), service("move").call(Pose.class, p, 2.5));
    Plan plan = new Plan("pick", List.of(p, new Pose(0, 0, 0, null)),
        new LinkedHashMap<>(Map.of("left", Gripper.OPEN)), Set.of(1, 2, 3));
    assertTravels(plan);
    Plan built = service("plan").call(Plan.class, "place", plan.steps(), plan.grips());
    assertEquals(new Plan("place", plan.steps(), plan.grips(), Set.of(2)), built);
  }

  @Test
  void dataClassesArriveFieldByField() throws TRADEException {
    Waypoint w = new Waypoint("dock", 1, 2, new int[] {5, 6}, List.of("charging"), Gripper.CLOSED,
        new Pose(1, 2, 0, "map"));
    Waypoint back = (Waypoint) echo(w);
    assertNotSame(w, back);
    assertWaypointEquals(w, back);
    assertEquals("not sent", back.cache, "transient fields do not travel");

    Waypoint renamed = service("renamed").call(Waypoint.class, w, "home");
    assertEquals("home", renamed.label);
    assertEquals("dock", w.label, "the provider changed its own copy");

    Checkpoint c = new Checkpoint();
    c.label = "gate";
    c.weights = new int[] {1};
    c.reachedAtMillis = 1234;
    Checkpoint cBack = (Checkpoint) echo(c);
    assertWaypointEquals(c, cBack);
    assertEquals(1234, cBack.reachedAtMillis);
  }

  private static void assertWaypointEquals(Waypoint expected, Waypoint actual) {
    assertSame(expected.getClass(), actual.getClass());
    assertEquals(expected.label, actual.label);
    assertEquals(expected.x, actual.x);
    assertEquals(expected.y, actual.y);
    assertArrayEquals(expected.weights, actual.weights);
    assertEquals(expected.tags, actual.tags);
    assertSame(expected.grip, actual.grip);
    assertEquals(expected.pose, actual.pose);
  }

  @Test
  void serializableClassesAndAnnotationsTravelToo() throws TRADEException {
    assertTravels(new Token("abc"));
    Marker marker = Marked.class.getAnnotation(Marker.class);
    Object back = echo(marker);
    assertEquals(marker, back);
    assertEquals(3, ((Marker) back).level());
    assertArrayEquals(new String[] {"arm", "left"}, ((Marker) back).tags());
  }

  /** A service of the consumer that the provider calls back through the info it was given. */
  public static final class Greeter {
    final AtomicInteger calls = new AtomicInteger();

    @TRADEService
    public String greet(String name) {
      calls.incrementAndGet();
      return "hello " + name;
    }
  }

  @Test
  void serviceInfosCanBeCalledBackAndStayEqual() throws TRADEException {
    Greeter greeter = new Greeter();
    TRADEServiceInfo greet = consumer.registerAllServices(greeter, "consumer").iterator().next();
    try {
      assertEquals("hello provider", service("callBack").call(String.class, greet, "provider"));
      assertEquals(1, greeter.calls.get());
      assertEquals(List.of("greet(java.lang.String)", "consumer", "false"),
          service("describeInfo").call(List.class, greet));

      TRADEServiceInfo back = service("echoInfo").call(TRADEServiceInfo.class, greet);
      assertEquals(greet, back);
      assertEquals(greet.hashCode(), back.hashCode());
      assertTrue(back.isLocal());
      assertEquals("hello again", back.call(String.class, "again"));

      // One of the provider's own infos, sent to it and back.
      TRADEServiceInfo echo = service("echo");
      TRADEServiceInfo echoBack = (TRADEServiceInfo) echo(echo);
      assertEquals(echo, echoBack);
      assertFalse(echoBack.isLocal());
      assertEquals("still callable", echoBack.call(String.class, "still callable"));
    } finally {
      consumer.deregister(greeter);
    }
  }
}
