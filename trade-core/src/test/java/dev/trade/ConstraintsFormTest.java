package dev.trade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import dev.trade.internal.codec.AllowList;
import dev.trade.internal.codec.Codec;
import dev.trade.internal.codec.InfoBinding;
import dev.trade.internal.codec.Limits;
import dev.trade.internal.system.ConstraintsForm;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The language-neutral form of service constraints (docs/protocol.md, "Service constraints"): what
 * it writes, that it reads back what it wrote, the documented example byte for byte, and a typed
 * error naming the key for every bad form.
 */
class ConstraintsFormTest {
  private final Codec codec = new Codec(AllowList.withDefaults(), Limits.DEFAULT,
      InfoBinding.DESCRIPTORS);

  private static Map<String, Object> map(Object... keysAndValues) {
    Map<String, Object> m = new LinkedHashMap<>();
    for (int i = 0; i < keysAndValues.length; i += 2) {
      m.put((String) keysAndValues[i], keysAndValues[i + 1]);
    }
    return m;
  }

  private static TRADEServiceConstraints roundTrip(TRADEServiceConstraints c) throws Exception {
    return ConstraintsForm.decode(ConstraintsForm.encode(c.toQuery()));
  }

  private static String refused(Object form) {
    return assertThrows(TRADEBadArgumentsException.class, () -> ConstraintsForm.decode(form))
        .getMessage();
  }

  @Test
  void everyConstraintSurvivesTheRoundTrip() throws Exception {
    TRADEServiceConstraints all = new TRADEServiceConstraints().name("move")
        .argTypes(int.class, String[].class, double[][].class, Map.Entry.class)
        .returnType(void.class).inGroups("robot", "arm").notInGroups("Sim").local().host("robot1")
        .notOnHost("lab", "cloud").onLocalhost()
        .not(new TRADEServiceConstraints().inGroups("broken"))
        .or(new TRADEServiceConstraints().name("stop").argTypes().notOnLocalhost()
            .or(new TRADEServiceConstraints().returnType(Integer.class)));
    assertEquals(all, roundTrip(all));
    assertEquals(new TRADEServiceConstraints(), roundTrip(new TRADEServiceConstraints()));
    TRADEServiceConstraints elsewhere = new TRADEServiceConstraints().notOnLocalhost();
    assertEquals(elsewhere, roundTrip(elsewhere));
    assertEquals(map(), ConstraintsForm.encode(new TRADEServiceConstraints().toQuery()));
  }

  @Test
  void writesOnlyWhatIsSetWithTypeNamesAsGetTypeNameSpellsThem() {
    TRADEServiceConstraints c = new TRADEServiceConstraints().name("add")
        .argTypes(int.class, String[].class).inGroups("math").onLocalhost();
    assertEquals(map("name", "add", "argTypes", List.of("int", "java.lang.String[]"),
        "inGroups", List.of("math"), "onLocalhost", true), ConstraintsForm.encode(c.toQuery()));
  }

  @Test
  void theDocumentedExampleByteForByte() throws Exception {
    Map<String, Object> form = map("name", "openGripper", "argTypes", List.of("int"),
        "inGroups", List.of("robot"), "or", List.of(map("name", "closeGripper")));
    String hex = "22 04 0A 04 6E 61 6D 65 0A 0B 6F 70 65 6E 47 72 69 70 70 65 72 0A 08 61 72 67 54"
        + " 79 70 65 73 20 01 0A 03 69 6E 74 0A 08 69 6E 47 72 6F 75 70 73 20 01 0A 05 72 6F 62 6F"
        + " 74 0A 02 6F 72 20 01 22 01 0A 04 6E 61 6D 65 0A 0C 63 6C 6F 73 65 47 72 69 70 70 65 72";
    assertEquals(hex, HexFormat.ofDelimiter(" ").withUpperCase().formatHex(codec.encode(form)));
    TRADEServiceConstraints expected = new TRADEServiceConstraints().name("openGripper")
        .argTypes(int.class).inGroups("robot")
        .or(new TRADEServiceConstraints().name("closeGripper"));
    Object decoded = codec.decode(HexFormat.of().parseHex(hex.replace(" ", "")),
        getClass().getClassLoader());
    assertEquals(expected, ConstraintsForm.decode(decoded));
    assertEquals(form, ConstraintsForm.encode(expected.toQuery()));
  }

  @Test
  void nullValuesAndSetsAreAccepted() throws Exception {
    Map<String, Object> form = map("name", null, "inGroups", new java.util.LinkedHashSet<>(List.of("a")),
        "local", false);
    assertEquals(new TRADEServiceConstraints().inGroups("a"), ConstraintsForm.decode(form));
  }

  @Test
  void badFormsAreRefusedNamingTheKey() {
    assertEquals("Constraints: constraints must be a map of constraints; got 'dock'",
        refused("dock"));
    assertEquals("Constraints: constraints has an unknown key 'nmae'; the keys are name, argTypes,"
        + " returnType, inGroups, notInGroups, local, host, onLocalhost, notOnHost, not, or",
        refused(map("nmae", "dock")));
    assertEquals("Constraints: constraints has an unknown key java.lang.Integer 1; the keys are name,"
        + " argTypes, returnType, inGroups, notInGroups, local, host, onLocalhost, notOnHost, not, or",
        refused(Map.of(1, "dock")));
    assertEquals("Constraints: constraints.name must be a non-empty string; got java.lang.Integer 3",
        refused(map("name", 3)));
    assertEquals("Constraints: constraints.name must be a non-empty string; got ''",
        refused(map("name", "")));
    assertEquals("Constraints: constraints.argTypes must be a list; got 'int'",
        refused(map("argTypes", "int")));
    assertEquals("Constraints: constraints.argTypes[1] must be a non-empty string; got null",
        refused(map("argTypes", java.util.Arrays.asList("int", null))));
    assertEquals("Constraints: constraints.argTypes[1] names type 'com.acme.Nowhere', which is not"
        + " known here; give a type name as Class.getTypeName() spells it (int, java.lang.String,"
        + " double[])", refused(map("argTypes", List.of("int", "com.acme.Nowhere"))));
    assertEquals("Constraints: constraints.returnType names type 'java.lang.Strng', which is not known here; give"
        + " a type name as Class.getTypeName() spells it (int, java.lang.String, double[])",
        refused(map("returnType", "java.lang.Strng")));
    assertEquals("Constraints: constraints.local must be true or false; got 'yes'",
        refused(map("local", "yes")));
    assertEquals("Constraints: constraints.onLocalhost must be true or false; got java.lang.Long 1",
        refused(map("onLocalhost", 1L)));
    assertEquals("Constraints: constraints.inGroups[0] must be a non-empty string; got"
        + " java.lang.Integer 7", refused(map("inGroups", List.of(7))));
    assertEquals("Constraints: constraints.or[1].not[0].host must be a non-empty string; got"
        + " java.lang.Boolean true", refused(map("or", List.of(map(),
            map("not", List.of(map("host", true)))))));
    assertEquals("Constraints: constraints.not[0] must be a map of constraints; got 'x'",
        refused(map("not", List.of("x"))));
  }

  @Test
  void nestingIsBounded() throws Exception {
    Map<String, Object> form = map("name", "deep");
    for (int i = 0; i < 8; i++) {
      form = map("or", List.of(form));
    }
    ConstraintsForm.decode(form);
    String message = refused(map("or", List.of(form)));
    assertEquals("Constraints: constraints" + ".or[0]".repeat(9) + " nests 'not' and 'or' deeper"
        + " than 8 levels", message);
  }
}
