package dev.trade.internal.codec;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ObjectInputFilter;
import java.util.List;
import org.junit.jupiter.api.Test;

class AllowListTest {

  @Test
  void defaultsAllowJdkValuePackagesAndTheApiOnly() {
    AllowList allow = AllowList.withDefaults();
    assertTrue(allow.isAllowed("java.lang.String"));
    assertTrue(allow.isAllowed("java.util.ArrayList"));
    assertTrue(allow.isAllowed("java.time.LocalDate"));
    assertTrue(allow.isAllowed("java.math.BigDecimal"));
    assertTrue(allow.isAllowed("dev.trade.TRADEException"));
    assertTrue(allow.isAllowed("java.io.IOException"));
    assertFalse(allow.isAllowed("java.lang.reflect.Method")); // not a subpackage
    assertFalse(allow.isAllowed("java.io.File"));
    assertFalse(allow.isAllowed("dev.trade.internal.registry.ServiceDescriptor"));
    assertFalse(allow.isAllowed("org.apache.commons.collections.functors.InvokerTransformer"));
  }

  @Test
  void patternKinds() {
    AllowList allow = AllowList.of("com.acme.*; org.robot.** ;edu.lab.Pose;edu.lab.Pre*;!org.robot.evil.*");
    assertTrue(allow.isAllowed("com.acme.Gripper"));
    assertTrue(allow.isAllowed("com.acme.Gripper$Jaw"));
    assertFalse(allow.isAllowed("com.acme.sub.Gripper"));
    assertTrue(allow.isAllowed("org.robot.Arm"));
    assertTrue(allow.isAllowed("org.robot.deep.er.Arm"));
    assertFalse(allow.isAllowed("org.robotics.Arm"));
    assertFalse(allow.isAllowed("org.robot.evil.Gadget")); // a refusal wins
    assertTrue(allow.isAllowed("edu.lab.Pose"));
    assertFalse(allow.isAllowed("edu.lab.Poser"));
    assertTrue(allow.isAllowed("edu.lab.Prefix"));
    assertFalse(allow.isAllowed("anything.Else"));
  }

  @Test
  void refusalAddedLaterStillWins() {
    AllowList allow = AllowList.of("com.acme.**");
    allow.add("!com.acme.Bad");
    assertFalse(allow.isAllowed("com.acme.Bad"));
    assertTrue(allow.isAllowed("com.acme.Good"));
  }

  @Test
  void arraysAreJudgedByElementTypeAndPrimitivesAlwaysPass() {
    AllowList allow = AllowList.of("com.acme.*");
    assertTrue(allow.isAllowed("[Lcom.acme.Pose;"));
    assertTrue(allow.isAllowed("[[Lcom.acme.Pose;"));
    assertFalse(allow.isAllowed("[Lorg.other.Pose;"));
    assertTrue(allow.isAllowed("[I"));
    assertTrue(allow.isAllowed("int"));
  }

  @Test
  void badPatternsAreRejectedAndNothingIsAdded() {
    AllowList allow = AllowList.of("com.acme.*");
    for (String bad : List.of("java.base/java.lang.*", "maxdepth=5", "com.*.x", "a b", "!", "**")) {
      assertThrows(IllegalArgumentException.class, () -> allow.add("org.ok.*;" + bad), bad);
    }
    assertEquals(List.of("com.acme.*"), allow.patterns());
  }

  @Test
  void addPackageOfAndFilterString() {
    AllowList allow = AllowList.of("!com.acme.Bad");
    allow.addPackageOf(AllowListTest[][].class);
    allow.addPackageOf(int.class);
    allow.addPackageOf(AllowListTest.class); // twice: kept once
    assertEquals(List.of("!com.acme.Bad", "dev.trade.internal.codec.*"), allow.patterns());
    assertEquals("!com.acme.Bad;dev.trade.internal.codec.*;!*", allow.toFilterString());
    // the JDK's own filter agrees with the string
    ObjectInputFilter jdk = ObjectInputFilter.Config.createFilter(allow.toFilterString());
    assertEquals(ObjectInputFilter.Status.ALLOWED, jdk.checkInput(info(AllowListTest.class)));
    assertEquals(ObjectInputFilter.Status.REJECTED, jdk.checkInput(info(String.class)));
  }

  @Test
  void filterAllowsExactlyWhatIsAllowed() {
    ObjectInputFilter filter = AllowList.withDefaults().filter();
    assertEquals(ObjectInputFilter.Status.ALLOWED, filter.checkInput(info(String.class)));
    assertEquals(ObjectInputFilter.Status.ALLOWED, filter.checkInput(info(long[].class)));
    assertEquals(ObjectInputFilter.Status.REJECTED, filter.checkInput(info(AllowListTest.class)));
    assertEquals(ObjectInputFilter.Status.REJECTED, filter.checkInput(info(AllowListTest[].class)));
    assertEquals(ObjectInputFilter.Status.UNDECIDED, filter.checkInput(info(null)));
  }

  private static ObjectInputFilter.FilterInfo info(Class<?> type) {
    return new ObjectInputFilter.FilterInfo() {
      @Override
      public Class<?> serialClass() {
        return type;
      }

      @Override
      public long arrayLength() {
        return -1;
      }

      @Override
      public long depth() {
        return 1;
      }

      @Override
      public long references() {
        return 1;
      }

      @Override
      public long streamBytes() {
        return 10;
      }
    };
  }
}
