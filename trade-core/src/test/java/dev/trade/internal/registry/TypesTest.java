package dev.trade.internal.registry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.lang.invoke.MethodType;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Boxing of primitive classes, which every call's argument and return checks use. */
class TypesTest {
  @Test
  void everyPrimitiveBoxesAsTheJdkDoes() {
    for (Class<?> p : List.of(boolean.class, byte.class, short.class, char.class, int.class,
        long.class, float.class, double.class, void.class)) {
      assertSame(MethodType.methodType(p).wrap().returnType(), Types.box(p), p.getName());
    }
  }

  @Test
  void otherClassesAreThemselves() {
    for (Class<?> c : List.of(Integer.class, String.class, int[].class, Object.class)) {
      assertSame(c, Types.box(c));
    }
    assertEquals(Integer.class, Types.box(Types.primitive("int")));
  }
}
