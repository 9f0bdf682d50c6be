package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.math.BigDecimal;
import java.time.DayOfWeek;
import java.time.Instant;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The worked examples of docs/protocol.md, byte for byte. */
class WireFormatTest {
  private final Codec codec = TestTypes.codec();

  private static byte[] hex(String spaced) {
    return HexFormat.of().parseHex(spaced.replace(" ", ""));
  }

  private void assertEncoding(Object value, String expected) throws Exception {
    byte[] bytes = codec.encode(value);
    assertEquals(expected, HexFormat.ofDelimiter(" ").withUpperCase().formatHex(bytes));
    Object back = codec.decode(bytes, loader());
    if (value != null && value.getClass().isArray()) {
      assertSame(value.getClass(), back.getClass());
    } else {
      assertEquals(value, back);
    }
  }

  @Test
  void examplesFromTheSpecification() throws Exception {
    assertEncoding(null, "00");
    assertEncoding(true, "02");
    assertEncoding(1, "05 00 00 00 01");
    assertEncoding(-2, "05 FF FF FF FE");
    assertEncoding(300L, "06 00 00 00 00 00 00 01 2C");
    assertEncoding(1.5, "08 3F F8 00 00 00 00 00 00");
    assertEncoding('A', "09 00 41");
    assertEncoding("héllo", "0A 06 68 C3 A9 6C 6C 6F");
    assertEncoding(new byte[] {1, 2, 3}, "10 03 01 02 03");
    assertEncoding(new int[] {1, -1}, "14 02 00 00 00 01 FF FF FF FF");
    assertEncoding(List.of(true, (byte) -1), "20 02 02 03 FF");
    assertEncoding(Set.of("s"), "21 01 0A 01 73");
    Map<String, Long> map = new LinkedHashMap<>();
    map.put("a", 1L);
    assertEncoding(map, "22 01 0A 01 61 06 00 00 00 00 00 00 00 01");
    assertEncoding(new String[] {"x"},
        "18 10 6A 61 76 61 2E 6C 61 6E 67 2E 53 74 72 69 6E 67 01 0A 01 78");
    assertEncoding(DayOfWeek.MONDAY,
        "30 13 6A 61 76 61 2E 74 69 6D 65 2E 44 61 79 4F 66 57 65 65 6B 06 4D 4F 4E 44 41 59");
    assertEncoding(new BigDecimal("-1.25"), "41 00 00 00 02 01 83");
    assertEncoding(Instant.ofEpochSecond(1, 5), "43 00 00 00 00 00 00 00 01 00 00 00 05");
    assertEncoding(int.class, "36 03 69 6E 74");
  }

  @Test
  void recordExample() throws Exception {
    ByteSink expected = new ByteSink();
    expected.writeByte(0x31);
    expected.writeText(TestTypes.Point.class.getName()); // the document uses com.acme.Point
    expected.writeBytes(hex("02 01 78 05 00 00 00 01 01 79 05 00 00 00 02"));
    assertArrayEquals(expected.toByteArray(), codec.encode(new TestTypes.Point(1, 2)));
    assertArrayEquals(hex("0E 63 6F 6D 2E 61 63 6D 65 2E 50 6F 69 6E 74"),
        text("com.acme.Point"));
  }

  @Test
  void exceptionExample() throws Exception {
    IllegalStateException e = new IllegalStateException("no");
    e.setStackTrace(new StackTraceElement[] {new StackTraceElement("Arm", "move", "Arm.java", 7)});
    byte[] expected = hex("33"
        + "1F 6A 61 76 61 2E 6C 61 6E 67 2E 49 6C 6C 65 67 61 6C 53 74 61 74 65"
        + "45 78 63 65 70 74 69 6F 6E"
        + "03 6E 6F 01 00 00 00 03 41 72 6D 04 6D 6F 76 65 09 41 72 6D 2E 6A 61 76 61"
        + "00 00 00 07 00");
    assertArrayEquals(expected, codec.encode(e));
    Throwable back = (Throwable) codec.decode(expected, loader());
    assertSame(IllegalStateException.class, back.getClass());
    assertEquals("no", back.getMessage());
    assertArrayEquals(e.getStackTrace(), back.getStackTrace());
  }

  @Test
  void uvarintExamples() {
    ByteSink sink = new ByteSink();
    for (int v : new int[] {0, 127, 128, 300, Integer.MAX_VALUE}) {
      sink.writeVarUInt(v);
    }
    assertArrayEquals(hex("00 7F 80 01 AC 02 FF FF FF FF 07"), sink.toByteArray());
  }

  private static byte[] text(String s) {
    ByteSink sink = new ByteSink();
    sink.writeText(s);
    return sink.toByteArray();
  }
}
