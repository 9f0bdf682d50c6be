package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.TestTypes.Color;
import dev.trade.internal.codec.TestTypes.FakeInfo;
import dev.trade.internal.codec.TestTypes.Holder;
import dev.trade.internal.codec.TestTypes.Labeled;
import dev.trade.internal.codec.TestTypes.Legacy;
import dev.trade.internal.codec.TestTypes.Point;
import dev.trade.internal.codec.TestTypes.Pose;
import java.math.BigDecimal;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.UUID;
import org.junit.jupiter.api.Test;

/**
 * Hostile and corrupt input must fail with {@link MalformedValueException} (or, for well-formed
 * values naming a refused or unknown class, its superclass) and never with an unchecked exception,
 * an error such as OutOfMemoryError or StackOverflowError, or a hang.
 */
class HostileInputTest {
  private final Codec codec = TestTypes.codec();

  private static final int ALL_TAGS_MASK = 0xFF;

  /** Valid encodings of values of every kind, to truncate and mutate (also by {@link ValueFuzzTest}). */
  static List<byte[]> samples(Codec codec) throws Exception {
    ArrayDeque<Object> deque = new ArrayDeque<>(List.of("a", 1));
    Object[] values = {
      null, true, (byte) 1, (short) 2, 3, 4L, 5f, 6d, 'c', "text ☃",
      new byte[] {1, 2}, new boolean[] {true}, new short[] {3}, new char[] {'x'}, new int[] {4},
      new long[] {5}, new float[] {6}, new double[] {7}, new String[] {"s", null},
      new Point[] {new Point(1, 2)}, TestTypes.nested(), Color.RED,
      new Labeled("l", new Point(1, 2), List.of("t"), 0.5, Color.BLUE), new Pose(1, 2, 3, "f"),
      new IllegalStateException("bad", new java.io.IOException("io")),
      new FakeInfo(TestTypes.descriptor(ServiceInfoCodingTest.Annotated.class
          .getMethod("moveTo", double.class, double.class).getAnnotations())),
      new BigDecimal("-3.14159"), UUID.fromString("00112233-4455-6677-8899-aabbccddeeff"),
      Instant.ofEpochSecond(1_700_000_000L, 123_456_789), java.time.Duration.ZERO,
      String.class, new Legacy("java"), deque, Map.of(List.of(1), new Holder(null)),
    };
    List<byte[]> samples = new ArrayList<>();
    for (Object v : values) {
      samples.add(codec.encode(v));
    }
    return samples;
  }

  private void assertMalformed(Codec c, byte[] bytes) {
    try {
      Object v = c.decode(bytes, loader());
      fail("decoded " + v + " from " + HexFormat.of().formatHex(bytes, 0, Math.min(64, bytes.length)));
    } catch (MalformedValueException e) {
      assertFalse(e.getMessage().startsWith("internal decoding error"), e::getMessage);
    } catch (TRADESerializationException e) {
      fail("not reported as malformed: " + e, e);
    }
  }

  /** Either a value or a checked decoding failure; never anything else. */
  private void assertDecodesOrFailsCleanly(byte[] bytes) {
    try {
      codec.decode(bytes, loader());
    } catch (TRADESerializationException e) {
      assertFalse(e.getMessage().startsWith("internal decoding error"), e::getMessage);
    }
  }

  @Test
  void everyTruncationOfValidEncodingsIsMalformed() throws Exception {
    int count = 0;
    for (byte[] sample : samples(codec)) {
      for (int length = 0; length < sample.length; length++) {
        assertMalformed(codec, Arrays.copyOf(sample, length));
        count++;
      }
    }
    assertTrue(count > 1000, "only " + count + " truncations");
  }

  @Test
  void randomBytesNeverEscapeAsUncheckedExceptionsOrErrors() {
    Random random = new Random(0x7EADE);
    int malformed = 0;
    int cases = 50_000;
    for (int i = 0; i < cases; i++) {
      byte[] bytes = new byte[random.nextInt(64)];
      random.nextBytes(bytes);
      if (bytes.length > 0 && i % 2 == 0) {
        bytes[0] = (byte) (random.nextInt(0x51) & ALL_TAGS_MASK); // mostly valid tags: go deeper
      }
      try {
        codec.decode(bytes, loader());
      } catch (MalformedValueException e) {
        malformed++;
        assertFalse(e.getMessage().startsWith("internal decoding error"), e::getMessage);
      } catch (TRADESerializationException e) {
        // random bytes may spell a well-formed value naming an unknown or refused class
        assertTrue(e.getMessage().contains("not known here")
            || e.getMessage().contains(AllowList.CONFIG_KEY), e::getMessage);
      }
    }
    assertTrue(malformed > cases * 9 / 10, malformed + " of " + cases);
  }

  @Test
  void randomlyMutatedValidEncodingsFailCleanly() throws Exception {
    Random random = new Random(42);
    List<byte[]> samples = samples(codec);
    for (int i = 0; i < 20_000; i++) {
      byte[] bytes = samples.get(random.nextInt(samples.size())).clone();
      if (bytes.length == 0) {
        continue;
      }
      for (int flips = 1 + random.nextInt(3); flips > 0; flips--) {
        bytes[random.nextInt(bytes.length)] = (byte) random.nextInt(256);
      }
      assertDecodesOrFailsCleanly(bytes);
    }
  }

  @Test
  void hugeClaimedCountsAreRejectedBeforeAllocating() {
    byte[] max = {(byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, 0x07}; // 2^31-1
    int[] counted = {Tags.STRING, Tags.BYTES, Tags.BOOLEANS, Tags.SHORTS, Tags.CHARS, Tags.INTS,
        Tags.LONGS, Tags.FLOATS, Tags.DOUBLES, Tags.LIST, Tags.SET, Tags.MAP, Tags.BIG_INTEGER,
        Tags.JAVA};
    for (int tag : counted) {
      assertMalformed(codec, concat(new byte[] {(byte) tag}, max));
      assertMalformed(codec, concat(new byte[] {(byte) tag, (byte) 0x80, (byte) 0x80, 0x01}, new byte[8]));
    }
    ByteSink array = new ByteSink();
    array.writeByte(Tags.ARRAY);
    array.writeText("java.lang.String");
    array.writeBytes(max);
    assertMalformed(codec, array.toByteArray());
    ByteSink record = new ByteSink();
    record.writeByte(Tags.RECORD);
    record.writeText(Point.class.getName());
    record.writeBytes(max);
    assertMalformed(codec, record.toByteArray());
    ByteSink frames = new ByteSink();
    frames.writeByte(Tags.THROWABLE);
    frames.writeText("x.Y");
    frames.writeByte(0);
    frames.writeBytes(max);
    assertMalformed(codec, frames.toByteArray());
  }

  @Test
  void limitsAreEnforced() throws Exception {
    Codec small = TestTypes.codec(new Limits(1024, 8, 100, 2));
    assertMalformed(small, codec.encode(new byte[2000])); // maxBytes
    assertMalformed(small, codec.encode(new int[101])); // maxElements
    assertMalformed(small, codec.encode("x".repeat(101)));
    assertMalformed(small, codec.encode(new Exception("three frames or more")));
    assertEquals(100, ((int[]) small.decode(codec.encode(new int[100]), loader())).length);
    Object deep = null;
    for (int i = 0; i < 9; i++) {
      deep = List.of(deep == null ? List.of() : deep);
    }
    assertMalformed(small, codec.encode(deep)); // maxDepth
  }

  @Test
  void aJavaSerializedArrayLongerThanItsBytesIsRejectedBeforeItIsAllocated() throws Exception {
    Codec roomy = TestTypes.codec(new Limits(1 << 20, 64, Integer.MAX_VALUE - 8, 100));
    byte[] bytes = codec.encode(new ArrayDeque<Object>(List.of(new long[] {1, 2, 3, 4})));
    // The long[]'s length follows its class descriptor: "[J", serialVersionUID, flags, no
    // fields, end of block data, no superclass.
    int at = indexOf(bytes, new byte[] {'[', 'J'}) + 2 + 8 + 1 + 2 + 1 + 1;
    assertEquals(4, ByteBuffer.wrap(bytes).getInt(at));
    ByteBuffer.wrap(bytes).putInt(at, Integer.MAX_VALUE - 16); // 16 GB of longs, in 32 bytes
    assertMalformed(roomy, bytes);
  }

  @Test
  void aCodecForTablesRefusesJavaSerializedValues() throws Exception {
    Codec tables = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.DESCRIPTORS, false);
    byte[] java = codec.encode(new ArrayDeque<Object>(List.of("a"))); // travels Java-serialized
    assertEquals(Tags.JAVA, java[0]);
    assertMalformed(tables, java);
    byte[] inAList = codec.encode(List.of(1, new ArrayDeque<Object>(List.of("a"))));
    assertMalformed(tables, inAList);
    assertEquals(List.of(1, "x"), tables.decode(codec.encode(List.of(1, "x")), loader()));
  }

  private static int indexOf(byte[] in, byte[] part) {
    for (int i = 0; i + part.length <= in.length; i++) {
      if (Arrays.equals(in, i, i + part.length, part, 0, part.length)) {
        return i;
      }
    }
    throw new AssertionError("not found");
  }

  @Test
  void depthBombsAreRejected() throws Exception {
    int levels = 1_000_000;
    byte[] lists = new byte[levels * 2 + 1];
    for (int i = 0; i < levels; i++) {
      lists[2 * i] = Tags.LIST;
      lists[2 * i + 1] = 1;
    }
    assertMalformed(codec, lists);

    ByteSink causes = new ByteSink();
    for (int i = 0; i < 10_000; i++) {
      causes.writeByte(Tags.THROWABLE);
      causes.writeText("x.E");
      causes.writeByte(0);
      causes.writeByte(0);
    }
    causes.writeByte(Tags.NULL);
    assertMalformed(codec, causes.toByteArray());

    ByteSink holders = new ByteSink();
    for (int i = 0; i < 10_000; i++) {
      holders.writeByte(Tags.RECORD);
      holders.writeText(Holder.class.getName());
      holders.writeVarUInt(1);
      holders.writeText("value");
    }
    holders.writeByte(Tags.NULL);
    assertMalformed(codec, holders.toByteArray());

    ArrayDeque<Object> javaDeep = new ArrayDeque<>(); // travels with Java serialization
    for (int i = 0; i < 200; i++) {
      ArrayDeque<Object> outer = new ArrayDeque<>();
      outer.add(javaDeep);
      javaDeep = outer;
    }
    assertMalformed(codec, codec.encode(javaDeep));
  }

  /**
   * Lists nested 60 deep, each claiming about as many elements as bytes are left: each count
   * alone fits, and each level pre-sized a list for it (about 92 MB for these 384 KiB). Counts are
   * now checked together, so the second level's claim is refused before anything is allocated.
   */
  @Test
  void nestedCountClaimsAreBoundedTogether() {
    int size = 384 << 10;
    ByteSink out = new ByteSink();
    for (int level = 0; level < 60; level++) {
      out.writeByte(Tags.LIST);
      out.writeVarUInt(size - 4 * (level + 1)); // about what is left after this count
    }
    while (out.size() < size) {
      out.writeByte(Tags.NULL);
    }
    byte[] bytes = out.toByteArray();
    try {
      Object v = TestTypes.codec(new Limits(1 << 20, 64, 1 << 20, 100)).decode(bytes, loader());
      fail("decoded " + v);
    } catch (TRADESerializationException e) {
      // Refused at the second level's count (it ends at offset 8), before its list was allocated.
      assertTrue(e instanceof MalformedValueException, e::toString);
      assertTrue(e.getMessage().matches("count \\d+ at offset 8 needs at least \\d+ bytes beside "
          + "the \\d+ that the rest of the values around it need, \\d+ left"), e::getMessage);
    }
    // The example of docs/protocol.md: the inner list's 3 and the outer list's 2 to come need 5
    // bytes, and 3 are left; with an inner list of 1 they fit.
    assertMalformed(codec, HexFormat.of().parseHex("20032003000000"));
    assertEquals(Arrays.asList(Arrays.asList((Object) null), null, null),
        assertDecodes("20032001000000"));
    // Nesting that the bytes do back still decodes: a list of lists of lists.
    List<Object> nested = List.of(List.of(List.of(1, 2), List.of()), List.of(3), List.of());
    assertTrue(nested.equals(decode(nested)));
  }

  /**
   * Sets nested in sets, each holding the next level twice: every level doubles the hash codes
   * computed while reading (20 levels took 0.45 s of a core; 50 far more than a call's deadline).
   * A Java-serialized value nests at most JavaSerialization.MAX_DEPTH levels, so such a value is
   * refused at once, while one within the bound decodes quickly.
   */
  @Test
  void aHashSetBombInAJavaSerializedValueIsRefusedByItsDepth() throws Exception {
    byte[] bomb = javaValue(hashSetBomb(24)); // 3.6 s of a core when it was decoded
    long start = System.nanoTime();
    try {
      codec.decode(bomb, loader());
      fail("a hash-set bomb 24 levels deep was decoded");
    } catch (MalformedValueException e) {
      assertTrue(e.getMessage().contains(JavaSerialization.MAX_DEPTH + " levels"), e::getMessage);
    }
    System.out.printf("a 24-level hash-set bomb was refused in %.1f ms%n",
        (System.nanoTime() - start) / 1e6);
    Object within = codec.decode(javaValue(hashSetBomb(JavaSerialization.MAX_DEPTH - 2)), loader());
    assertTrue(within instanceof java.util.HashSet);
  }

  /** The nested sets of a serialization bomb, {@code levels} deep. */
  private static java.util.Set<Object> hashSetBomb(int levels) {
    java.util.Set<Object> root = new java.util.HashSet<>();
    java.util.Set<Object> s1 = root;
    java.util.Set<Object> s2 = new java.util.HashSet<>();
    for (int i = 0; i < levels; i++) {
      java.util.Set<Object> t1 = new java.util.HashSet<>();
      java.util.Set<Object> t2 = new java.util.HashSet<>();
      t1.add("foo"); // t1 differs from t2
      s1.add(t1);
      s1.add(t2);
      s2.add(t1);
      s2.add(t2);
      s1 = t1;
      s2 = t2;
    }
    return root;
  }

  /** {@code value} as a JAVA value: the tag, the length and the serialized bytes. */
  private static byte[] javaValue(Object value) throws java.io.IOException {
    java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
    try (java.io.ObjectOutputStream out = new java.io.ObjectOutputStream(bytes)) {
      out.writeObject(value);
    }
    ByteSink sink = new ByteSink();
    sink.writeByte(Tags.JAVA);
    sink.writeVarUInt(bytes.size());
    sink.writeBytes(bytes.toByteArray(), 0, bytes.size());
    return sink.toByteArray();
  }

  private Object assertDecodes(String hex) {
    try {
      return codec.decode(HexFormat.of().parseHex(hex), loader());
    } catch (TRADESerializationException e) {
      throw new AssertionError(hex, e);
    }
  }

  private Object decode(Object value) {
    try {
      return codec.decode(codec.encode(value), loader());
    } catch (TRADESerializationException e) {
      throw new AssertionError(e);
    }
  }

  @Test
  void malformedPrimitivesAreRejected() {
    String[] hex = {
      "0B", "19", "7F", "80", "FF", // unknown and reserved tags
      "0A0180", "0A02C080", "0A03EDA080", "0A04F4908080", "0A02E282", "0A03E228A1", "0A01FF",
      "0A8000", "0AFFFFFFFF0F", "0A808080808000", // non-minimal, too large, too long varints
      "110102", // boolean array element 2
      "4000", // big integer without bytes
      "437FFFFFFFFFFFFFFF00000000", // instant out of range
      "44000000000000000040000000", // nanoseconds out of range
      "3106636F6D2E2E7800", // record type name "com..x"
      "18013100", // object array with component type name "1"
      "3303782E590000", // exception "x.Y", no message, no frames, and no cause value
      "1803696E740100", // object array of primitive component type "int"
    };
    for (String h : hex) {
      assertMalformed(codec, HexFormat.of().parseHex(h));
    }
    ByteSink tooManyDimensions = new ByteSink(); // its elements would need 256 dimensions
    tooManyDimensions.writeByte(Tags.ARRAY);
    tooManyDimensions.writeText("[".repeat(255) + "I");
    tooManyDimensions.writeVarUInt(0);
    assertMalformed(codec, tooManyDimensions.toByteArray());
  }

  @Test
  void annotationEntryLengthMustMatch() throws Exception {
    byte[] bytes = codec.encode(new FakeInfo(TestTypes.descriptor(ServiceInfoCodingTest.Annotated.class
        .getMethod("plain").getAnnotations())));
    // the encodings with and without annotations first differ in the annotation count; the first
    // entry follows it
    byte[] without = codec.encode(new FakeInfo(TestTypes.descriptor()));
    int at = Arrays.mismatch(bytes, without) + 1;
    assertEquals(2, bytes[at - 1]);
    int length = ByteBuffer.wrap(bytes, at, 4).getInt();
    for (int bad : new int[] {length - 1, length + 1, 100_000, 0, -5, Integer.MIN_VALUE}) {
      byte[] changed = bytes.clone();
      ByteBuffer.wrap(changed, at, 4).putInt(bad);
      assertMalformed(codec, changed);
    }
  }

  /**
   * An annotation entry is well-formed or refused, whether its type is known here and it is
   * decoded or not and it is skipped: its members are read as far as their grammar goes, without
   * loading a class.
   */
  @Test
  void anAnnotationEntryDecodedOrSkippedMustBeWellFormed() throws Exception {
    TestTypes.Action action = ServiceInfoCodingTest.Annotated.class
        .getMethod("moveTo", double.class, double.class).getAnnotation(TestTypes.Action.class);
    byte[] known = codec.encode(new FakeInfo(TestTypes.descriptor(action)));
    int entry = indexOf(known, codec.encode(action), 0);
    byte[] unknown = known.clone();
    byte[] name = TestTypes.Action.class.getName().getBytes(StandardCharsets.UTF_8);
    unknown[indexOf(unknown, name, entry) + name.length - 1] = 'X'; // a type this JVM does not have
    assertEquals(List.of(action), ((FakeInfo) codec.decode(known, loader())).descriptor.annotations());
    assertEquals(List.of(), ((FakeInfo) codec.decode(unknown, loader())).descriptor.annotations());

    for (byte[] bytes : List.of(known, unknown)) {
      List<byte[]> broken = new ArrayList<>();
      byte[] shorter = bytes.clone(); // the value's last byte outside the entry
      ByteBuffer.wrap(shorter).putInt(entry - 4, ByteBuffer.wrap(bytes).getInt(entry - 4) - 1);
      broken.add(shorter);
      int priorityTag = indexOf(bytes, ascii("priority"), entry) + "priority".length();
      assertEquals(Tags.INT32, bytes[priorityTag]);
      for (int tag : new int[] {0x7F, Tags.LIST, Tags.NULL, Tags.JAVA}) { // unknown, or not a member's
        broken.add(changed(bytes, priorityTag, tag));
      }
      broken.add(changed(bytes, indexOf(bytes, ascii("move"), entry), 0xFF)); // not UTF-8
      byte[] className = ascii("[Ljava.lang.String;");
      broken.add(changed(bytes, indexOf(bytes, className, entry) + className.length - 1, '!'));
      byte[] inner = TestTypes.Inner.class.getName().getBytes(StandardCharsets.UTF_8);
      broken.add(changed(bytes, indexOf(bytes, inner, entry) + inner.length, 0x7F)); // 127 members
      for (byte[] b : broken) {
        assertMalformed(codec, b);
      }
    }
  }

  private static byte[] ascii(String s) {
    return s.getBytes(StandardCharsets.US_ASCII);
  }

  private static byte[] changed(byte[] bytes, int at, int value) {
    byte[] c = bytes.clone();
    c[at] = (byte) value;
    return c;
  }

  private static int indexOf(byte[] haystack, byte[] needle, int from) {
    for (int i = from; i + needle.length <= haystack.length; i++) {
      if (Arrays.equals(haystack, i, i + needle.length, needle, 0, needle.length)) {
        return i;
      }
    }
    throw new AssertionError("not found: " + HexFormat.of().formatHex(needle));
  }

  private static byte[] concat(byte[] a, byte[] b) {
    byte[] c = Arrays.copyOf(a, a.length + b.length);
    System.arraycopy(b, 0, c, a.length, b.length);
    return c;
  }
}
