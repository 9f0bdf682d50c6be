package dev.trade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.lang.module.ModuleDescriptor;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/** The module exports the API package only; the JDK is its only dependency. */
class ModuleExportsTest {
  @Test
  void onlyTheApiPackageIsExported() throws IOException, URISyntaxException {
    Path classes = Path.of(TRADE.class.getProtectionDomain().getCodeSource().getLocation().toURI());
    try (InputStream in = Files.newInputStream(classes.resolve("module-info.class"))) {
      ModuleDescriptor d = ModuleDescriptor.read(in);
      assertEquals("dev.trade", d.name());
      assertEquals(Set.of("dev.trade"),
          d.exports().stream().map(ModuleDescriptor.Exports::source).collect(Collectors.toSet()));
      assertTrue(d.requires().stream().allMatch(r -> r.name().startsWith("java.")),
          d.requires().toString());
      assertTrue(d.packages().stream().filter(p -> !p.equals("dev.trade"))
          .allMatch(p -> p.startsWith("dev.trade.internal")), d.packages().toString());
    }
  }
}
