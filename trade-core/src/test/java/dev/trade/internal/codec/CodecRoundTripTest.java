package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.codec;
import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.TestTypes.Legacy;
import dev.trade.internal.codec.TestTypes.NotCodable;
import dev.trade.internal.codec.TestTypes.Point;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Date;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.LinkedList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.UUID;
import org.junit.jupiter.api.Test;

class CodecRoundTripTest {
  private final Codec codec = codec();

  private Object roundTrip(Object value) throws TRADESerializationException {
    return codec.decode(codec.encode(value), loader());
  }

  private void assertSameValueAndType(Object value) throws TRADESerializationException {
    Object back = roundTrip(value);
    assertEquals(value, back);
    assertSame(value.getClass(), back.getClass());
  }

  @Test
  void scalarsKeepTheirJavaType() throws Exception {
    assertNull(roundTrip(null));
    for (Object v : List.of(true, false, (byte) -7, (short) 300, 7, -1, Integer.MIN_VALUE,
        Long.MAX_VALUE, 1.5f, -0.0f, Float.NaN, 2.25, Double.NEGATIVE_INFINITY, 'q', '\uFFFF',
        "", "hello", "grüße ☃ \uD83E\uDD16", "x".repeat(100_000))) {
      assertSameValueAndType(v);
    }
    assertEquals(Float.floatToRawIntBits(Float.intBitsToFloat(0x7FC00001)),
        Float.floatToRawIntBits((Float) roundTrip(Float.intBitsToFloat(0x7FC00001))));
  }

  @Test
  void unpairedSurrogateBecomesReplacementCharacter() throws Exception {
    assertEquals("a\uFFFDb\uFFFD", roundTrip("a\uD800b\uDC00"));
    assertEquals("\uFFFD".repeat(50), roundTrip("\uD800".repeat(50)));
  }

  @Test
  void primitiveArrays() throws Exception {
    assertArrayEquals(new byte[] {1, -2, 3}, (byte[]) roundTrip(new byte[] {1, -2, 3}));
    assertArrayEquals(new boolean[] {true, false}, (boolean[]) roundTrip(new boolean[] {true, false}));
    assertArrayEquals(new short[] {-1, 2}, (short[]) roundTrip(new short[] {-1, 2}));
    assertArrayEquals(new char[] {'a', '\u20AC'}, (char[]) roundTrip(new char[] {'a', '\u20AC'}));
    assertArrayEquals(new int[] {0, -5, Integer.MAX_VALUE}, (int[]) roundTrip(new int[] {0, -5, Integer.MAX_VALUE}));
    assertArrayEquals(new long[] {Long.MIN_VALUE, 3}, (long[]) roundTrip(new long[] {Long.MIN_VALUE, 3}));
    assertArrayEquals(new float[] {1.5f, Float.NaN}, (float[]) roundTrip(new float[] {1.5f, Float.NaN}));
    assertArrayEquals(new double[] {-2.5, 1e300}, (double[]) roundTrip(new double[] {-2.5, 1e300}));
    assertArrayEquals(new int[0], (int[]) roundTrip(new int[0]));
  }

  @Test
  void sixteenMegabyteByteArray() throws Exception {
    byte[] big = new byte[16 * 1024 * 1024];
    new Random(1).nextBytes(big);
    byte[] encoded = codec.encode(big);
    assertEquals(1 + 4 + big.length, encoded.length); // tag, 4-byte varint, data
    assertArrayEquals(big, (byte[]) codec.decode(encoded, loader()));
  }

  @Test
  void objectArraysComeBackTyped() throws Exception {
    String[] strings = {"a", null, "c"};
    Object back = roundTrip(strings);
    assertSame(String[].class, back.getClass());
    assertArrayEquals(strings, (String[]) back);

    TestTypes.Term[] terms = {new TestTypes.Pose(1, 2, 3, "map"), null};
    Object termsBack = roundTrip(terms);
    assertSame(TestTypes.Term[].class, termsBack.getClass());
    assertArrayEquals(terms, (Object[]) termsBack);

    Point[] points = {new Point(1, 2), new Point(3, 4)};
    assertArrayEquals(points, (Point[]) roundTrip(points));

    int[][] grid = {{1, 2}, {3}};
    int[][] gridBack = (int[][]) roundTrip(grid);
    assertTrue(Arrays.deepEquals(grid, gridBack));

    String[][] names = {{"a"}, {}};
    assertTrue(Arrays.deepEquals(names, (String[][]) roundTrip(names)));

    Object[] mixed = {1, "two", List.of(3), new byte[] {4}};
    Object[] mixedBack = (Object[]) roundTrip(mixed);
    assertSame(Object[].class, mixedBack.getClass());
    assertArrayEquals((byte[]) mixed[3], (byte[]) mixedBack[3]);
  }

  @Test
  void collectionsDecodeAsArrayListLinkedHashSetLinkedHashMap() throws Exception {
    assertSame(ArrayList.class, roundTrip(new LinkedList<>(List.of(1, 2))).getClass());
    assertEquals(List.of(1, 2), roundTrip(List.of(1, 2)));
    Set<?> set = (Set<?>) roundTrip(new TreeSet<>(List.of("c", "a", "b")));
    assertSame(LinkedHashSet.class, set.getClass());
    assertEquals(List.of("a", "b", "c"), new ArrayList<>(set)); // order kept
    Map<?, ?> map = (Map<?, ?>) roundTrip(new TreeMap<>(Map.of(3, "c", 1, "a")));
    assertSame(LinkedHashMap.class, map.getClass());
    assertEquals(List.of(1, 3), new ArrayList<>(map.keySet()));
    assertEquals(TestTypes.nested(), roundTrip(TestTypes.nested()));
    List<Object> withNull = new ArrayList<>();
    withNull.add(null);
    assertEquals(withNull, roundTrip(withNull));
  }

  @Test
  void otherCollectionsKeepTheirClassWhenSerializableElseBecomeLists() throws Exception {
    ArrayDeque<String> deque = new ArrayDeque<>(List.of("a", "b"));
    Object back = roundTrip(deque);
    assertSame(ArrayDeque.class, back.getClass());
    assertEquals(List.of("a", "b"), new ArrayList<>((ArrayDeque<?>) back));
    Map<String, Integer> map = new HashMap<>(Map.of("k", 1));
    assertEquals(List.of(1), roundTrip(map.values()));
  }

  @Test
  void jdkValueTypes() throws Exception {
    for (Object v : List.of(BigInteger.ZERO, BigInteger.valueOf(-129), BigInteger.TWO.pow(521),
        new BigDecimal("-12345.678900"), BigDecimal.valueOf(1, -3), UUID.randomUUID(),
        Instant.ofEpochSecond(-5, 999_999_999), Instant.MAX, Instant.MIN, Duration.ofMillis(-1),
        Duration.ofSeconds(Long.MAX_VALUE, 999_999_999))) {
      assertSameValueAndType(v);
    }
    assertSame(int.class, roundTrip(int.class));
    assertSame(String[].class, roundTrip(String[].class));
    assertSame(Point.class, roundTrip(Point.class));
    assertEquals(new Date(1234), roundTrip(new Date(1234))); // Java serialization, java.util
  }

  @Test
  void serializableClassWithHooksTravelsAsJavaSerialization() throws Exception {
    byte[] bytes = codec.encode(new Legacy("old"));
    assertEquals(Tags.JAVA, bytes[0]);
    assertEquals(new Legacy("old"), codec.decode(bytes, loader()));
  }

  @Test
  void unsupportedValueNamesItsClass() {
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> codec.encode(List.of(new Point(1, 2), new NotCodable(3))));
    assertTrue(e.getMessage().contains(NotCodable.class.getName()), e.getMessage());
    assertTrue(e.getMessage().contains("no no-argument constructor"), e.getMessage());

    TRADESerializationException inRecord = assertThrows(TRADESerializationException.class,
        () -> codec.encode(new TestTypes.Holder(new NotCodable(3))));
    assertTrue(inRecord.getMessage().contains("component value of " + TestTypes.Holder.class.getName()),
        inRecord.getMessage());
  }

  @Test
  void cycleFailsWithDepthErrorNamingTheClass() {
    List<Object> cyclic = new ArrayList<>();
    cyclic.add(cyclic);
    TRADESerializationException e =
        assertThrows(TRADESerializationException.class, () -> codec.encode(cyclic));
    assertTrue(e.getMessage().contains("java.util.ArrayList"), e.getMessage());
    assertTrue(e.getMessage().contains("cyclic"), e.getMessage());
  }

  @Test
  void failedWriteLeavesSinkUnchanged() throws Exception {
    ByteSink sink = new ByteSink();
    codec.write("kept", sink);
    int size = sink.size();
    assertThrows(TRADESerializationException.class,
        () -> codec.write(List.of("x", new NotCodable(1)), sink));
    assertEquals(size, sink.size());
    assertEquals("kept", codec.decode(sink.toByteArray(), loader()));
  }

  @Test
  void encodingBeyondLimitsFails() throws Exception {
    Codec small = codec(new Limits(1024, 64, 1 << 20, 100));
    assertThrows(TRADESerializationException.class, () -> small.encode(new byte[2000]));
    assertThrows(TRADESerializationException.class,
        () -> small.encode(java.util.Collections.nCopies(600, 1)));
    Codec few = codec(new Limits(1 << 20, 64, 10, 100));
    assertThrows(TRADESerializationException.class, () -> few.encode(new int[11]));
    assertThrows(TRADESerializationException.class, () -> few.encode(List.of(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11)));
    assertThrows(TRADESerializationException.class, () -> few.encode("é".repeat(6)));
    assertEquals("é".repeat(5), few.decode(few.encode("é".repeat(5)), loader()));
  }

  @Test
  void valuesFollowEachOtherInOneSource() throws Exception {
    ByteSink sink = new ByteSink(0);
    codec.write(1, sink);
    codec.write("two", sink);
    codec.write(List.of(3), sink);
    ByteSource in = ByteSource.of(sink.array(), 0, sink.size());
    assertEquals(1, codec.read(in, loader()));
    assertEquals("two", codec.read(in, loader()));
    assertEquals(List.of(3), codec.read(in, loader()));
    assertEquals(0, in.remaining());
  }

  @Test
  void trailingBytesAreMalformed() throws Exception {
    byte[] bytes = Arrays.copyOf(codec.encode(5), 6);
    assertThrows(MalformedValueException.class, () -> codec.decode(bytes, loader()));
  }

  @Test
  void decodedValueIsAssignableWhereTheSenderDeclaredIt() throws Exception {
    Object back = roundTrip(List.of(new Point(1, 2)));
    assertInstanceOf(Point.class, ((List<?>) back).get(0));
  }
}
