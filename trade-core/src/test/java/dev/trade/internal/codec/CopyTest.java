package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.codec;
import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.TestTypes.Color;
import dev.trade.internal.codec.TestTypes.Holder;
import dev.trade.internal.codec.TestTypes.Labeled;
import dev.trade.internal.codec.TestTypes.Legacy;
import dev.trade.internal.codec.TestTypes.Point;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import org.junit.jupiter.api.Test;

class CopyTest {
  private final Codec codec = codec();

  @Test
  void immutableValuesAreReturnedAsTheyAre() throws Exception {
    assertNull(codec.copy(null, loader()));
    for (Object v : List.of("text", 1, 2L, (byte) 3, (short) 4, 5f, 6d, 'c', true,
        Color.RED, BigInteger.TEN, new BigDecimal("1.50"), UUID.randomUUID(), Instant.now(),
        Duration.ofSeconds(3), String.class, new Point(1, 2), new Holder("s"),
        new Holder(new Holder(Color.BLUE)), new FakeInfoHolder().info)) {
      assertSame(v, codec.copy(v, loader()), String.valueOf(v));
    }
  }

  @Test
  void mutableValuesAreCopiedEqualButDistinct() throws Exception {
    List<Object> list = new ArrayList<>(List.of(1, "a"));
    assertCopied(list);
    Map<String, Object> map = new HashMap<>(Map.of("k", new ArrayList<>(List.of(1))));
    assertCopied(map);
    assertCopied(new Legacy("serialized"));
    Labeled labeled = new Labeled("l", new Point(0, 0), new ArrayList<>(List.of("t")), 1, Color.RED);
    assertCopied(labeled); // a record holding a mutable list
    assertCopied(new Holder(list));

    int[] ints = {1, 2, 3};
    int[] copy = (int[]) codec.copy(ints, loader());
    assertNotSame(ints, copy);
    assertArrayEquals(ints, copy);

    Point[] points = {new Point(1, 2)};
    Point[] pointsCopy = (Point[]) codec.copy(points, loader());
    assertNotSame(points, pointsCopy);
    assertSame(Point[].class, pointsCopy.getClass());
    assertEquals(points[0], pointsCopy[0]);
  }

  private void assertCopied(Object value) throws TRADESerializationException {
    Object copy = codec.copy(value, loader());
    assertNotSame(value, copy);
    assertEquals(value, copy);
  }

  @Test
  void refusedSerializableClassNamesClassAndConfigurationKey() {
    Codec stranger = TestTypes.strangerCodec();
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> stranger.copy(new Legacy("x"), loader()));
    assertFalse(e instanceof MalformedValueException);
    assertTrue(e.getMessage().contains(Legacy.class.getName()), e.getMessage());
    assertTrue(e.getMessage().contains(AllowList.CONFIG_KEY), e.getMessage());
  }

  @Test
  void refusalIsLiftedByAddingAPatternAtRunTime() throws Exception {
    Codec stranger = TestTypes.strangerCodec();
    assertThrows(TRADESerializationException.class, () -> stranger.copy(new Legacy("x"), loader()));
    stranger.allowList().addPackageOf(Legacy.class);
    assertEquals(new Legacy("x"), stranger.copy(new Legacy("x"), loader()));
  }

  /** Holds a service info made by the fake binding. */
  private static final class FakeInfoHolder {
    final TestTypes.FakeInfo info = new TestTypes.FakeInfo(TestTypes.descriptor());
  }
}
