package dev.trade.internal.registry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.example.jvm.diarc.language.LanguageInterface;
import org.example.jvm.diarc.language.Utterance;
import org.example.jvm.diarc.symbols.Symbol;
import org.junit.jupiter.api.Test;

/** Which classes a signature declares: type arguments, bounds, fields and superclasses. */
class DeclaredTypesTest {
  static class Base {
    Symbol inherited;
  }

  static class Holder extends Base {
    Map<String, List<Utterance>> byName;
    transient Thread notCarried;
    static Runnable notAField;
  }

  interface Service {
    <T extends Symbol> Holder find(T[] bounded, Set<? super Utterance> wildcard)
        throws IllegalStateException;
  }

  @Test
  void signaturesDeclareTypeArgumentsBoundsFieldsAndSuperclasses() throws Exception {
    Set<String> names = DeclaredTypes.of(Service.class.getMethod("find", Symbol[].class, Set.class));
    for (Class<?> c : List.of(Holder.class, Base.class, Symbol.class, Utterance.class,
        String.class, Map.class, List.class, Set.class, IllegalStateException.class)) {
      assertTrue(names.contains(c.getName()), c + " in " + names);
    }
    assertFalse(names.contains(Thread.class.getName()), "transient fields are not carried");
    assertFalse(names.contains(Runnable.class.getName()), "static fields are not carried");
  }

  @Test
  void aRemoteSignatureCountsForTheClassesThisJvmHas() throws Exception {
    String generic = LanguageInterface.class.getMethod("understand", Set.class).getGenericReturnType()
        .getTypeName();
    assertEquals(Set.of(Utterance.class.getName(), String.class.getName(), List.class.getName(),
        Symbol.class.getName()), DeclaredTypes.of(generic, List.of(), getClass().getClassLoader()));
    Set<String> names = DeclaredTypes.of("java.util.Map<com.acme.Missing, ? extends "
        + Symbol.class.getName() + ">[]", List.of("com.acme.MissingException",
        IllegalStateException.class.getName()), getClass().getClassLoader());
    assertEquals(Set.of(Map.class.getName(), Symbol.class.getName(), String.class.getName(),
        IllegalStateException.class.getName()), names);
  }
}
