package dev.trade.internal.net.remote;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trade.internal.call.CallContext;
import dev.trade.internal.codec.ByteSink;
import dev.trade.internal.codec.ByteSource;
import dev.trade.internal.codec.MalformedValueException;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The call context's rules on the wire (docs/protocol.md, "Call context"). */
class ContextCodingTest {
  private static byte[] written(CallContext c) {
    ByteSink out = new ByteSink(64);
    ContextCoding.write(c, out);
    return out.toByteArray();
  }

  private static CallContext read(byte[] b) throws MalformedValueException {
    return ContextCoding.read(ByteSource.of(b, 0, b.length));
  }

  @Test
  void anEmptyContextIsNotWrittenAndNoBytesReadAsEmpty() throws Exception {
    assertEquals(0, written(CallContext.EMPTY).length);
    assertEquals(CallContext.EMPTY, read(new byte[0]));
    assertEquals(CallContext.EMPTY, read(new byte[] {0}));
  }

  @Test
  void unknownKeysTravelInKeyOrder() throws Exception {
    CallContext c = CallContext.of(Map.of("zz.app", "1", "a.b", "", "trade.future", "x"));
    assertEquals(c, read(written(c)));
    assertEquals("[a.b, trade.future, zz.app]", c.entries().keySet().toString());
  }

  @Test
  void keysOutOfOrderOrTooManyAreMalformed() {
    byte[] unordered = {2, 1, 'b', 0, 1, 'a', 0};
    assertThrows(MalformedValueException.class, () -> read(unordered));
    byte[] tooMany = {17};
    assertThrows(MalformedValueException.class, () -> read(tooMany));
    byte[] badKey = {1, 1, 'A', 0};
    assertThrows(MalformedValueException.class, () -> read(badKey));
  }
}
