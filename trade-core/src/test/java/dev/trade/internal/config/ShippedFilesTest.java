package dev.trade.internal.config;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Keeps {@code config/trade.properties} and {@code docs/configuration.md} in step with
 * {@link Settings}: adding a key without documenting and shipping it fails here. Paths are
 * relative to the trade-core module directory, where Surefire runs.
 */
class ShippedFilesTest {
  private static final Path SHIPPED = Path.of("..", "config", "trade.properties");
  private static final Path DOCS = Path.of("..", "docs", "configuration.md");
  // | `KEY` | default | meaning | takes effect |
  private static final Pattern KEY_ROW =
      Pattern.compile("^\\|\\s*`([A-Z_]+)`\\s*\\|\\s*([^|]*?)\\s*\\|([^|]*)\\|([^|]*)\\|\\s*$");

  @Test
  void shippedFileLoadsAsTheDefaults() throws IOException {
    Properties p = new Properties();
    try (Reader in = Files.newBufferedReader(SHIPPED, StandardCharsets.UTF_8)) {
      p.load(in);
    }
    assertEquals(Settings.defaults(), Settings.fromProperties(p));
  }

  @Test
  void shippedFileSpellsOutEveryKeyInOrderWithItsCanonicalDefault() throws IOException {
    Map<String, String> written = new LinkedHashMap<>();
    List<String> lines = Files.readAllLines(SHIPPED, StandardCharsets.UTF_8);
    for (int i = 0; i < lines.size(); i++) {
      String line = lines.get(i);
      if (line.isBlank() || line.startsWith("#")) {
        continue;
      }
      int eq = line.indexOf('=');
      written.put(line.substring(0, eq), line.substring(eq + 1));
      assertTrue(i > 0 && lines.get(i - 1).startsWith("# "),
          "no one-line comment above " + line);
    }
    assertSameKeys(SHIPPED, written);
    assertEquals(Settings.defaults().asMap(), written);
  }

  @Test
  void docsTableListsEveryKeyWithItsDefault() throws IOException {
    Map<String, String> documented = new LinkedHashMap<>();
    for (String row : keysSectionRows()) {
      Matcher m = KEY_ROW.matcher(row);
      assertTrue(m.matches(), "not a | `KEY` | default | meaning | takes effect | row: " + row);
      String shown = m.group(2);
      String value = shown.equals("(empty)") ? "" : shown.replaceAll("^`|`$", "");
      documented.put(m.group(1), value);
      assertTrue(!m.group(3).isBlank() && !m.group(4).isBlank(), "empty cell in: " + row);
    }
    assertSameKeys(DOCS, documented);
    assertEquals(Settings.defaults().asMap(), documented);
  }

  /** Names the keys that are missing or extra, then checks that the order is canonical. */
  private static void assertSameKeys(Path file, Map<String, String> found) {
    List<String> expected = List.copyOf(Settings.defaults().asMap().keySet());
    Set<String> missing = new TreeSet<>(expected);
    missing.removeAll(found.keySet());
    Set<String> extra = new TreeSet<>(found.keySet());
    extra.removeAll(expected);
    assertTrue(missing.isEmpty() && extra.isEmpty(),
        file + ": missing keys " + missing + ", unknown keys " + extra);
    assertEquals(expected, List.copyOf(found.keySet()), file + ": keys out of canonical order");
  }

  /** The table rows of the "## Keys" section, without its header and separator rows. */
  private static List<String> keysSectionRows() throws IOException {
    List<String> rows = new ArrayList<>();
    boolean inSection = false;
    for (String line : Files.readAllLines(DOCS, StandardCharsets.UTF_8)) {
      if (line.startsWith("## ")) {
        inSection = line.equals("## Keys");
      } else if (inSection && line.startsWith("| `")) {
        rows.add(line);
      }
    }
    assertTrue(!rows.isEmpty(), "no key rows under '## Keys' in " + DOCS.toAbsolutePath());
    return rows;
  }
}
