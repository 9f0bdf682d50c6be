package dev.trade.internal.config;

import static java.nio.charset.StandardCharsets.ISO_8859_1;
import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Resolution order of {@link Settings#load}: system property, environment, working directory,
 * class path, then defaults.
 */
class SettingsLoadTest {
  private static final Function<String, String> UNSET = name -> null;

  @TempDir Path dir;

  /** Loads with a working directory that holds no trade.properties. */
  private Settings load(Function<String, String> properties, Function<String, String> environment,
      ClassLoader loader) {
    return Settings.load(properties, environment, dir.resolve("empty"), loader);
  }

  @Test
  void aFileInTheWorkingDirectoryComesAfterTheNamedFilesAndBeforeTheClassPath() throws IOException {
    Path cwd = Files.createDirectories(dir.resolve("cwd"));
    Files.writeString(cwd.resolve("trade.properties"), "CONTAINERNAME=from-working-directory\n");
    Path fromEnv = write("env.properties", "CONTAINERNAME=from-env\n");
    ClassLoader withResource = loaderWith("CONTAINERNAME=from-class-path\n");
    assertEquals("from-working-directory",
        Settings.load(UNSET, UNSET, cwd, withResource).containerName());
    assertEquals("from-env", Settings.load(UNSET, only(Settings.PATH_ENV, fromEnv.toString()), cwd,
        withResource).containerName());
    assertEquals("from-class-path",
        Settings.load(UNSET, UNSET, dir.resolve("empty"), withResource).containerName());
  }

  @Test
  void systemPropertyBeatsEnvironmentBeatsClassPathBeatsDefaults() throws IOException {
    Path fromProperty = write("property.properties", "CONTAINERNAME=from-property\n");
    Path fromEnv = write("env.properties", "CONTAINERNAME=from-env\n");
    ClassLoader withResource = loaderWith("CONTAINERNAME=from-class-path\n");
    Function<String, String> property = only(Settings.PATH_PROPERTY, fromProperty.toString());
    Function<String, String> env = only(Settings.PATH_ENV, fromEnv.toString());

    assertEquals("from-property",
        load(property, env, withResource).containerName());
    assertEquals("from-env",
        load(UNSET, env, withResource).containerName());
    assertEquals("from-class-path",
        load(UNSET, UNSET, withResource).containerName());
    assertSame(Settings.defaults(), load(UNSET, UNSET, emptyLoader()));
  }

  @Test
  void blankPathCountsAsUnset() throws IOException {
    Path fromEnv = write("env.properties", "CONTAINERNAME=from-env\n");
    assertEquals("from-env", load(
        only(Settings.PATH_PROPERTY, " "), only(Settings.PATH_ENV, fromEnv.toString()),
        emptyLoader()).containerName());
  }

  @Test
  void missingFileIsAnErrorNamingItAndDoesNotFallThrough() throws IOException {
    Path missing = dir.resolve("nope.properties");
    ClassLoader withResource = loaderWith("CONTAINERNAME=from-class-path\n");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
        load(only(Settings.PATH_PROPERTY, missing.toString()), UNSET, withResource));
    assertEquals("system property trade.properties.path=" + missing + ": no such file ("
        + missing.toAbsolutePath() + ")", e.getMessage());

    e = assertThrows(IllegalArgumentException.class, () ->
        load(UNSET, only(Settings.PATH_ENV, missing.toString()), withResource));
    assertEquals("environment variable TRADE_PROPERTIES_PATH=" + missing + ": no such file ("
        + missing.toAbsolutePath() + ")", e.getMessage());
  }

  @Test
  void directoryIsNotAFile() {
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
        load(only(Settings.PATH_PROPERTY, dir.toString()), UNSET, emptyLoader()));
    assertEquals("system property trade.properties.path=" + dir + ": not a regular file ("
        + dir.toAbsolutePath() + ")", e.getMessage());
  }

  @Test
  void badValueInAFileNamesTheFile() throws IOException {
    Path file = write("bad.properties", "# hub\nBROADCASTPORT = 70000\n");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
        load(only(Settings.PATH_PROPERTY, file.toString()), UNSET, emptyLoader()));
    assertEquals(file.toAbsolutePath() + ": BROADCASTPORT=70000: expected a port 1..65535",
        e.getMessage());
  }

  @Test
  void unknownKeyInAClassPathResourceNamesTheResource() throws IOException {
    ClassLoader loader = loaderWith("BROADCASTPROT=1\n");
    URL resource = loader.getResource("trade.properties");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
        load(UNSET, UNSET, loader));
    assertEquals(resource + ": unknown key 'BROADCASTPROT' (did you mean BROADCASTPORT?)",
        e.getMessage());
  }

  @Test
  void readsTradeHubFileAsDiarcWritesIt() throws IOException {
    // The hub profile PyTRADE ships (local_trade_hub.properties), plus a legacy key.
    Path file = write("hub.properties", String.join("\n",
        "STARTBROADCAST=false", "STARTDISCOVERY=false", "STARTACCEPTINGCONNECTIONS=true",
        "SERVERIPS=127.0.0.1@10002", "CONNECTCONTAINERS=", "SCANFORSERVER=false",
        "RUNWEBSERVER=false", ""));
    Settings s = load(only(Settings.PATH_PROPERTY, file.toString()), UNSET,
        emptyLoader());
    assertEquals(Settings.defaults().with("STARTACCEPTINGCONNECTIONS", "true")
        .with("SERVERIPS", "127.0.0.1@10002").with("SCANFORSERVER", "false"), s);
  }

  @Test
  void readsUtf8AndFallsBackToLatin1() throws IOException {
    Path utf8 = dir.resolve("utf8.properties");
    Files.write(utf8, "CONTAINERNAME=Bürobot\n".getBytes(UTF_8));
    Path latin1 = dir.resolve("latin1.properties");
    Files.write(latin1, "CONTAINERNAME=Bürobot\n".getBytes(ISO_8859_1));
    for (Path file : new Path[] {utf8, latin1}) {
      assertEquals("Bürobot", load(
          only(Settings.PATH_PROPERTY, file.toString()), UNSET, emptyLoader()).containerName());
    }
  }

  @Test
  void loadWithoutInjectionUsesTheRealSources() {
    // The test class path ships no trade.properties resource; the JVM may still name a file.
    assumeTrue(System.getProperty(Settings.PATH_PROPERTY) == null
        && System.getenv(Settings.PATH_ENV) == null
        && !Files.exists(Path.of(Settings.RESOURCE)), "a settings file is set for this JVM");
    assertSame(Settings.defaults(), Settings.load());
  }

  private Path write(String name, String content) throws IOException {
    return Files.writeString(dir.resolve(name), content);
  }

  private ClassLoader loaderWith(String content) throws IOException {
    Path root = Files.createDirectories(dir.resolve("classes-" + content.hashCode()));
    Files.writeString(root.resolve("trade.properties"), content);
    return new URLClassLoader(new URL[] {root.toUri().toURL()}, null);
  }

  private static ClassLoader emptyLoader() {
    return new URLClassLoader(new URL[0], null);
  }

  private static Function<String, String> only(String name, String value) {
    return Map.of(name, value)::get;
  }
}
