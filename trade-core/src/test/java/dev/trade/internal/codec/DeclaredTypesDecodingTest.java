package dev.trade.internal.codec;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADESerializationException;
import java.util.List;
import java.util.Set;
import org.example.jvm.diarc.language.Utterance;
import org.example.jvm.diarc.symbols.Symbol;
import org.junit.jupiter.api.Test;

/** Declared classes are decodable in a read that names them, and only there; refusals still win. */
class DeclaredTypesDecodingTest {
  private final Utterance value = new Utterance("hugo", List.of(new Symbol("cup", "object")));
  private final Set<String> declared = Set.of(Utterance.class.getName(), Symbol.class.getName());

  private static Object read(AllowList allow, byte[] bytes, Set<String> declared)
      throws TRADESerializationException {
    Codec codec = new Codec(allow, Limits.DEFAULT, InfoBinding.NONE);
    return codec.read(ByteSource.of(bytes), DeclaredTypesDecodingTest.class.getClassLoader(), declared);
  }

  @Test
  void declaredClassesDecodeInTheirReadOnly() throws Exception {
    byte[] bytes = TestTypes.codec().encode(value);
    AllowList defaults = AllowList.withDefaults();
    assertEquals(value, read(defaults, bytes, declared));
    TRADESerializationException e = assertThrows(TRADESerializationException.class,
        () -> read(defaults, bytes, Set.of()));
    assertTrue(e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    e = assertThrows(TRADESerializationException.class,
        () -> read(defaults, bytes, Set.of(Utterance.class.getName())));
    assertTrue(e.getMessage().contains(Symbol.class.getName()), e.getMessage());

    AllowList refusing = AllowList.withDefaults();
    refusing.add("!org.example.jvm.diarc.symbols.*");
    assertThrows(TRADESerializationException.class, () -> read(refusing, bytes, declared));
  }

  @Test
  void viewsFilterJavaSerializationAlike() {
    AllowList view = AllowList.withDefaults().with(Set.of(Symbol.class.getName()));
    assertTrue(view.isAllowed(Symbol.class.getName()));
    assertTrue(view.isAllowed("[L" + Symbol.class.getName() + ";"));
    assertTrue(view.toFilterString().endsWith(Symbol.class.getName() + ";!*"), view.toFilterString());
    assertThrows(IllegalStateException.class, () -> view.add("com.acme.*"));
  }
}
