package dev.trade.internal.admin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AccessFileTest {
  @Test
  void readsPrincipalsAndRules() {
    AccessFile f = AccessFile.parse("t", List.of(
        "# the lab's principals",
        "",
        "principal alice admin,operator alice-secret-1",
        "principal bob - bob-secret-22",
        "allow service moveArm operator",
        "allow group public *"));
    assertEquals(Set.of("admin", "operator"), f.principal("alice").roles());
    assertEquals("alice-secret-1", f.principal("alice").secret());
    assertEquals(Set.of(), f.principal("bob").roles());
    assertNull(f.principal("carol"));
    assertEquals(Set.of("operator"), f.serviceRule("moveArm"));
    assertEquals(Set.of("*"), f.groupRule("public"));
    assertFalse(f.principal("alice").toString().contains("secret-1"));
  }

  @Test
  void aBadLineFailsNamingTheLineAndNeverTheSecret(@TempDir Path dir) throws Exception {
    Path file = dir.resolve("principals");
    Files.writeString(file, "principal alice admin alice-secret-1\nprincipal bob admin\n");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> AccessFile.load(file));
    assertEquals("access file " + file + ", line 2: expected 'principal <name> <roles|-> <secret>'"
        + " (4 fields separated by spaces; the secret has no spaces), found 3 fields", e.getMessage());

    e = assertThrows(IllegalArgumentException.class, () -> AccessFile.parse("f",
        List.of("principal carol admin short")));
    assertEquals("access file f, line 1: the secret of principal 'carol' is shorter than 8"
        + " characters; use a long random secret", e.getMessage());
    e = assertThrows(IllegalArgumentException.class, () -> AccessFile.parse("f",
        List.of("", "principal d@ve admin dave-secret-1")));
    assertEquals("access file f, line 2: 'd@ve' is not a principal name: 1 to 64 of A-Z a-z 0-9"
        + " . _ -", e.getMessage());
    e = assertThrows(IllegalArgumentException.class, () -> AccessFile.parse("f",
        List.of("permit group x admin")));
    assertEquals("access file f, line 1: unknown entry 'permit'; a line is a comment (#),"
        + " 'principal ...' or 'allow ...'", e.getMessage());
  }

  @Test
  void credentialsNameAndHoldTheSecretButNeverShowIt() {
    Credentials c = Credentials.parse("alice:s3cret:with:colons");
    assertEquals("alice", c.principal());
    assertEquals("s3cret:with:colons", c.secret());
    assertEquals("alice:****", c.toString());
    assertEquals(Credentials.ANONYMOUS, Credentials.parse("diarcUser"));
    assertEquals(Credentials.ANONYMOUS, Credentials.parse(null));
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> Credentials.parse("a b:topsecret"));
    assertFalse(e.getMessage().contains("topsecret"));
  }
}
