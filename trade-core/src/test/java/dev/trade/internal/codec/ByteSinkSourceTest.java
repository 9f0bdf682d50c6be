package dev.trade.internal.codec;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.ByteBuffer;
import java.util.HexFormat;
import org.junit.jupiter.api.Test;

class ByteSinkSourceTest {

  @Test
  void numbersAreBigEndianAndReadBack() throws Exception {
    ByteSink sink = new ByteSink(0);
    sink.writeByte(0xAB);
    sink.writeShort(0x1234);
    sink.writeInt(0x01020304);
    sink.writeLong(0x0102030405060708L);
    sink.writeFloat(1.0f);
    sink.writeDouble(-2.0);
    assertEquals("AB123401020304010203040506070" + "83F800000C000000000000000",
        HexFormat.of().withUpperCase().formatHex(sink.toByteArray()));
    ByteSource in = ByteSource.of(sink.array(), 0, sink.size());
    assertEquals((byte) 0xAB, in.readByte());
    assertEquals(0x1234, in.readShort());
    assertEquals(0x01020304, in.readInt());
    assertEquals(0x0102030405060708L, in.readLong());
    assertEquals(1.0f, in.readFloat());
    assertEquals(-2.0, in.readDouble());
    assertEquals(0, in.remaining());
    assertThrows(MalformedValueException.class, in::readByte);
  }

  @Test
  void varintsRoundTripAtEveryBoundary() throws Exception {
    int[] values = {0, 1, 127, 128, 16383, 16384, 2097151, 2097152, 268435455, 268435456,
        Integer.MAX_VALUE};
    ByteSink sink = new ByteSink();
    for (int v : values) {
      sink.writeVarUInt(v);
    }
    ByteSource in = ByteSource.of(sink.toByteArray());
    for (int v : values) {
      assertEquals(v, in.readVarUInt());
    }
    assertThrows(IllegalArgumentException.class, () -> sink.writeVarUInt(-1));
  }

  @Test
  void textsOfEveryLengthClass() throws Exception {
    ByteSink sink = new ByteSink(1);
    String[] texts = {"", "a", "é".repeat(42), "é".repeat(43), "\uD83E\uDD16".repeat(30),
        "x".repeat(200_000)};
    for (String t : texts) {
      sink.writeText(t);
    }
    ByteSource in = ByteSource.of(sink.toByteArray());
    for (String t : texts) {
      assertEquals(t, in.readText(Integer.MAX_VALUE));
    }
    ByteSource limited = ByteSource.of(sink.toByteArray());
    limited.readText(0);
    limited.readText(1);
    assertThrows(MalformedValueException.class, () -> limited.readText(83));
  }

  @Test
  void slicesAndBuffersAreBoundsChecked() throws Exception {
    byte[] data = {9, 1, 2, 3, 4, 9};
    ByteSource slice = ByteSource.of(data, 1, 4);
    assertEquals(0x01020304, slice.readInt());
    assertEquals(4, slice.position());
    assertThrows(MalformedValueException.class, slice::readByte);
    assertThrows(IndexOutOfBoundsException.class, () -> ByteSource.of(data, 4, 3));

    ByteBuffer direct = ByteBuffer.allocateDirect(4).putShort((short) 7).putShort((short) 8).flip();
    direct.position(2);
    ByteSource fromDirect = ByteSource.of(direct);
    assertEquals(8, fromDirect.readShort());
    assertEquals(2, direct.position()); // the buffer's own position is unchanged
    ByteBuffer heap = ByteBuffer.wrap(data, 2, 3).slice();
    assertEquals(2, ByteSource.of(heap).readByte());

    byte[] target = new byte[2];
    ByteSource.of(data).readFully(target, 0, 2);
    assertArrayEquals(new byte[] {9, 1}, target);
  }

  @Test
  void putIntPatchesWrittenBytesOnly() {
    ByteSink sink = new ByteSink();
    sink.writeInt(0);
    sink.writeByte(5);
    sink.putInt(0, 1);
    assertArrayEquals(new byte[] {0, 0, 0, 1, 5}, sink.toByteArray());
    assertThrows(IndexOutOfBoundsException.class, () -> sink.putInt(2, 1));
    sink.reset();
    assertEquals(0, sink.size());
  }
}
