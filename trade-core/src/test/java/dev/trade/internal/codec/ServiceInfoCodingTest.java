package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.codec;
import static dev.trade.internal.codec.TestTypes.descriptor;
import static dev.trade.internal.codec.TestTypes.loader;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEService;
import dev.trade.internal.codec.TestTypes.Action;
import dev.trade.internal.codec.TestTypes.Color;
import dev.trade.internal.codec.TestTypes.FakeInfo;
import dev.trade.internal.codec.TestTypes.Inner;
import dev.trade.internal.registry.ServiceDescriptor;
import java.lang.annotation.Annotation;
import java.lang.reflect.Proxy;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ServiceInfoCodingTest {
  private final Codec codec = codec();

  @SuppressWarnings("unused")
  static final class Annotated {
    @TRADEService
    @Action(value = "move", priority = 2, tags = {"a", "b"}, color = Color.RED, type = String[].class,
        inner = @Inner(7), limits = {}, letter = '\u00E9', ratio = Double.NaN)
    public boolean moveTo(double x, double y) {
      return true;
    }

    @Deprecated(since = "1.0")
    @Action("defaults")
    public void plain() {}
  }

  private static Annotation[] annotationsOf(String method) throws Exception {
    for (java.lang.reflect.Method m : Annotated.class.getMethods()) {
      if (m.getName().equals(method)) {
        return m.getAnnotations();
      }
    }
    throw new AssertionError(method);
  }

  @Test
  void serviceInfoTravelsAsDescriptorAndIsBoundAgain() throws Exception {
    FakeInfo info = new FakeInfo(descriptor());
    byte[] bytes = codec.encode(info);
    assertEquals(Tags.SERVICE_INFO, bytes[0]);
    Object back = codec.decode(bytes, loader());
    FakeInfo bound = assertInstanceOf(FakeInfo.class, back);
    assertNotSame(info, bound);
    assertEquals(info, bound);
    assertEquals(info.hashCode(), bound.hashCode());
    assertEquals(List.of("agent:hugo", "motion"), new ArrayList<>(bound.descriptor.groups()));
  }

  @Test
  void serviceInfosInsideOtherValues() throws Exception {
    FakeInfo info = new FakeInfo(descriptor());
    assertEquals(List.of(info, new TestTypes.Holder(info)),
        codec.decode(codec.encode(List.of(info, new TestTypes.Holder(info))), loader()));
    assertSame(info, codec.copy(info, loader()));
  }

  @Test
  void annotationsAreRecreatedFollowingTheAnnotationContract() throws Exception {
    Annotation[] original = annotationsOf("moveTo");
    FakeInfo back = (FakeInfo) codec.decode(codec.encode(new FakeInfo(descriptor(original))), loader());
    List<Annotation> decoded = back.descriptor.annotations();
    assertEquals(original.length, decoded.size());
    for (int i = 0; i < original.length; i++) {
      Annotation a = original[i];
      Annotation b = decoded.get(i);
      assertTrue(Proxy.isProxyClass(b.getClass()));
      assertEquals(a, b);
      assertEquals(b, a); // the JDK's own implementation agrees
      assertEquals(a.hashCode(), b.hashCode());
      assertSame(a.annotationType(), b.annotationType());
    }
    Action action = (Action) decoded.get(1);
    assertEquals("move", action.value());
    assertEquals(2, action.priority());
    assertArrayEquals(new String[] {"a", "b"}, action.tags());
    assertSame(Color.RED, action.color());
    assertSame(String[].class, action.type());
    assertEquals(7, action.inner().value());
    assertEquals('\u00E9', action.letter());
    assertTrue(Double.isNaN(action.ratio()));
    action.tags()[0] = "changed";
    assertEquals("a", action.tags()[0]); // arrays are copied on every call
    assertTrue(action.toString().contains("value=\"move\""), action.toString());
    assertTrue(action.toString().startsWith("@" + Action.class.getName() + "("), action.toString());
    assertNotEquals(action, annotationsOf("plain")[1]);
    assertEquals(back.descriptor, descriptor(original)); // the descriptors are equal as values
  }

  /** A codec whose allow-list refuses this test package explicitly. */
  private static Codec refusingCodec() {
    AllowList refusing = AllowList.withDefaults();
    refusing.add("!dev.trade.internal.codec.*");
    return new Codec(refusing, Limits.DEFAULT, new TestTypes.FakeBinding());
  }

  @Test
  void annotationsAKnownClassOfWhichTheAllowListDoesNotNameAreDecoded() throws Exception {
    // The stranger's allow-list does not name this package; the annotation type and the enum and
    // annotation types its members declare (Color, Inner) are known here, so @Action arrives.
    ServiceDescriptor d = descriptor(annotationsOf("moveTo"));
    FakeInfo back = (FakeInfo) TestTypes.strangerCodec().decode(codec.encode(new FakeInfo(d)), loader());
    assertEquals(d.annotations(), back.descriptor.annotations());
    Action action = (Action) back.descriptor.annotations().get(1);
    assertSame(Color.RED, action.color());
  }

  @Test
  void annotationsWhoseClassIsRefusedOrUnknownAreSkipped() throws Exception {
    ServiceDescriptor d = descriptor(annotationsOf("plain"));
    FakeInfo back = (FakeInfo) refusingCodec().decode(codec.encode(new FakeInfo(d)), loader());
    List<Annotation> kept = back.descriptor.annotations();
    assertEquals(1, kept.size()); // @Deprecated (java.lang) stays, the refused package's @Action not
    Deprecated deprecated = assertInstanceOf(Deprecated.class, kept.get(0));
    assertEquals("1.0", deprecated.since());
    assertEquals(annotationsOf("plain")[0], deprecated);

    // The same name with one letter changed: a class this JVM does not have.
    byte[] bytes = codec.encode(new FakeInfo(d));
    byte[] name = Action.class.getName().getBytes(java.nio.charset.StandardCharsets.UTF_8);
    int at = indexOf(bytes, name);
    bytes[at + name.length - 1] = 'X';
    kept = ((FakeInfo) codec.decode(bytes, loader())).descriptor.annotations();
    assertEquals(List.of(annotationsOf("plain")[0]), kept);
  }

  private static int indexOf(byte[] haystack, byte[] needle) {
    outer:
    for (int i = 0; i + needle.length <= haystack.length; i++) {
      for (int j = 0; j < needle.length; j++) {
        if (haystack[i + j] != needle[j]) {
          continue outer;
        }
      }
      return i;
    }
    throw new AssertionError("not found");
  }

  @Test
  void annotationsAreValuesToo() throws Exception {
    Annotation action = annotationsOf("moveTo")[1];
    Object back = codec.decode(codec.encode(action), loader());
    assertEquals(action, back);
    assertSame(action, codec.copy(action, loader()));
    assertEquals(action, TestTypes.strangerCodec().decode(codec.encode(action), loader()));
    assertThrows(dev.trade.TRADESerializationException.class,
        () -> refusingCodec().decode(codec.encode(action), loader()));
  }

  @Test
  void aClassThatIsNotAnAnnotationIsRefusedInPlaceOfOne() throws Exception {
    byte[] bytes = codec.encode(annotationsOf("moveTo")[1]);
    String fake = Color.class.getName(); // same package, an enum: must not pass as an annotation
    String real = Action.class.getName();
    ByteSink out = new ByteSink(64);
    out.writeByte(Tags.ANNOTATION);
    out.writeText(fake);
    int headerLength = 1 + 1 + real.length();
    out.writeBytes(bytes, headerLength, bytes.length - headerLength);
    dev.trade.TRADESerializationException e = assertThrows(
        dev.trade.TRADESerializationException.class,
        () -> TestTypes.strangerCodec().decode(out.toByteArray(), loader()));
    assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
  }

  @Test
  void withoutBindingTheDescriptorItselfIsReturned() throws Exception {
    Codec plain = new Codec(AllowList.withDefaults(), Limits.DEFAULT, InfoBinding.NONE);
    ServiceDescriptor d = descriptor();
    Object back = plain.decode(codec.encode(new FakeInfo(d)), loader());
    assertEquals(d, back);
  }
}
