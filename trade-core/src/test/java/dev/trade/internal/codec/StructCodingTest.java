package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.codec;
import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADESerializationException;
import dev.trade.internal.codec.TestTypes.Color;
import dev.trade.internal.codec.TestTypes.Labeled;
import dev.trade.internal.codec.TestTypes.Op;
import dev.trade.internal.codec.TestTypes.Point;
import dev.trade.internal.codec.TestTypes.Pose;
import dev.trade.internal.codec.TestTypes.Positive;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

class StructCodingTest {
  private final Codec codec = codec();

  private Object roundTrip(Object value) throws TRADESerializationException {
    return codec.decode(codec.encode(value), loader());
  }

  @Test
  void recordsRebuiltThroughCanonicalConstructor() throws Exception {
    Labeled value = new Labeled("home", new Point(3, -4), List.of("a", "b"), 0.25, Color.BLUE);
    assertEquals(value, roundTrip(value));
    assertEquals(List.of(new Point(1, 1)), roundTrip(List.of(new Point(1, 1))));
  }

  @Test
  void recordConstructorRejectionIsReportedAsSerializationFailure() throws Exception {
    // write Positive(0) by hand: its compact constructor refuses it
    ByteSink out = new ByteSink();
    out.writeByte(Tags.RECORD);
    out.writeText(Positive.class.getName());
    out.writeVarUInt(1);
    out.writeText("value");
    out.writeByte(Tags.INT32);
    out.writeInt(0);
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> codec.decode(out.toByteArray(), loader()));
    assertFalse(e instanceof MalformedValueException);
    assertTrue(e.getMessage().contains("not positive: 0"), e.getMessage());
  }

  @Test
  void missingComponentsGetDefaultsAndUnknownOnesAreIgnored() throws Exception {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.RECORD);
    out.writeText(Point.class.getName());
    out.writeVarUInt(2);
    out.writeText("y");
    out.writeByte(Tags.INT32);
    out.writeInt(9);
    out.writeText("z"); // a newer sender's extra component
    out.writeByte(Tags.STRING);
    out.writeText("ignored");
    assertEquals(new Point(0, 9), codec.decode(out.toByteArray(), loader()));
  }

  @Test
  void wrongComponentTypeNamesTheComponent() {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.RECORD);
    out.writeText(Point.class.getName());
    out.writeVarUInt(1);
    out.writeText("x");
    out.writeByte(Tags.STRING);
    out.writeText("one");
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> codec.decode(out.toByteArray(), loader()));
    assertTrue(e.getMessage().contains("component x of " + Point.class.getName()), e.getMessage());
  }

  @Test
  void dataClassesKeepPrivateFinalAndSuperclassFields() throws Exception {
    Pose pose = new Pose(17, 1.5, -2.5, "map");
    pose.history().add(4);
    pose.sorted().put("b", 2);
    pose.sorted().put("a", 1);
    pose.cached = 99;
    pose.name = "derived";
    ((TestTypes.Base) pose).name = "from base";
    Pose back = (Pose) roundTrip(pose);
    assertEquals(pose, back);
    assertEquals("map", back.frame());
    assertEquals(7, back.cached); // transient: what the constructor leaves
    assertSame(TreeMap.class, back.sorted().getClass()); // adapted to the declared class
    assertEquals("from base", back.shadowedInBase());
  }

  @Test
  void dataClassEncodingUsesQualifiedNamesForShadowedFields() throws Exception {
    byte[] bytes = codec.encode(new Pose(1, 0, 0, "f"));
    String text = new String(bytes, java.nio.charset.StandardCharsets.ISO_8859_1);
    assertTrue(text.contains(TestTypes.Base.class.getName() + "#name"), text);
  }

  @Test
  void enumsIncludingConstantsWithBodies() throws Exception {
    assertSame(Color.GREEN, roundTrip(Color.GREEN));
    assertSame(Op.TIMES, roundTrip(Op.TIMES));
    assertEquals(Map.of(Color.RED, List.of(Op.PLUS)), roundTrip(Map.of(Color.RED, List.of(Op.PLUS))));
  }

  @Test
  void unknownEnumConstantIsReported() {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.ENUM);
    out.writeText(Color.class.getName());
    out.writeText("PURPLE");
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> codec.decode(out.toByteArray(), loader()));
    assertTrue(e.getMessage().contains("PURPLE"), e.getMessage());
  }

  @Test
  void classesNotAllowedAreRefusedBeforeLoadingWithTheConfigurationKey() throws Exception {
    byte[] bytes = codec.encode(new Point(1, 2));
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> TestTypes.strangerCodec().decode(bytes, loader()));
    assertFalse(e instanceof MalformedValueException);
    assertTrue(e.getMessage().contains(Point.class.getName()), e.getMessage());
    assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    assertTrue(e.getMessage().contains("dev.trade.internal.codec.*"), e.getMessage());
  }

  @Test
  void unknownClassIsReported() {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.RECORD);
    out.writeText("dev.trade.internal.codec.NoSuchRecord");
    out.writeVarUInt(0);
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> codec.decode(out.toByteArray(), loader()));
    assertTrue(e.getMessage().contains("not known here"), e.getMessage());
  }

  @Test
  void tagMustMatchTheKindOfClass() {
    ByteSink out = new ByteSink();
    out.writeByte(Tags.RECORD);
    out.writeText(Pose.class.getName()); // a data class, not a record
    out.writeVarUInt(0);
    assertThrows(TRADESerializationException.class, () -> codec.decode(out.toByteArray(), loader()));
    ByteSink object = new ByteSink();
    object.writeByte(Tags.OBJECT);
    object.writeText("java.lang.Thread"); // allowed package, but not a plain data class here
    object.writeVarUInt(0);
    assertThrows(TRADESerializationException.class, () -> codec.decode(object.toByteArray(), loader()));
  }

  @Test
  void copiesOfDataClassesAreDistinct() throws Exception {
    Pose pose = new Pose(3, 1, 2, "odom");
    Object copy = codec.copy(pose, loader());
    assertInstanceOf(Pose.class, copy);
    assertNotSame(pose, copy);
    assertEquals(pose, copy);
  }
}
