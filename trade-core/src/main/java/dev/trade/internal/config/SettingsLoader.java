package dev.trade.internal.config;

import java.io.IOException;
import java.io.InputStream;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.lang.System.Logger.Level;
import java.net.URL;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.Properties;
import java.util.function.Function;

/**
 * Resolves where the settings come from and reads them: the implementation of
 * {@link Settings#load()}. Stateless and safe for concurrent use.
 */
final class SettingsLoader {
  private static final System.Logger LOG = System.getLogger(Settings.class.getName());

  private SettingsLoader() {}

  static Settings load(
      Function<String, String> systemProperties,
      Function<String, String> environment,
      Path workingDirectory,
      ClassLoader loader) {
    Objects.requireNonNull(systemProperties, "systemProperties == null");
    Objects.requireNonNull(environment, "environment == null");
    Objects.requireNonNull(loader, "loader == null");
    // Blank counts as unset: launch scripts often export an empty variable.
    String property = blankToNull(systemProperties.apply(Settings.PATH_PROPERTY));
    String env = blankToNull(environment.apply(Settings.PATH_ENV));
    if (property != null) {
      if (env != null && !env.equals(property)) {
        LOG.log(Level.WARNING, "{0}={1} is used; {2}={3} is ignored",
            Settings.PATH_PROPERTY, property, Settings.PATH_ENV, env);
      }
      return fromFile(property, "system property " + Settings.PATH_PROPERTY);
    }
    if (env != null) {
      return fromFile(env, "environment variable " + Settings.PATH_ENV);
    }
    Path here = workingDirectory.resolve(Settings.RESOURCE);
    if (Files.isRegularFile(here)) {
      return fromFile(here.toString(), "the working directory's " + Settings.RESOURCE);
    }
    URL resource = loader.getResource(Settings.RESOURCE);
    if (resource != null) {
      return fromResource(resource);
    }
    LOG.log(Level.DEBUG, "no {0} file: using the built-in defaults", Settings.RESOURCE);
    return Settings.defaults();
  }

  private static Settings fromFile(String pathText, String origin) {
    Path path;
    try {
      path = Path.of(pathText);
    } catch (InvalidPathException e) {
      throw new IllegalArgumentException(origin + "=" + pathText + ": not a valid path", e);
    }
    if (!Files.isRegularFile(path)) {
      String problem = Files.exists(path) ? "not a regular file" : "no such file";
      throw new IllegalArgumentException(
          origin + "=" + pathText + ": " + problem + " (" + path.toAbsolutePath() + ")");
    }
    byte[] bytes;
    try {
      bytes = Files.readAllBytes(path);
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + path.toAbsolutePath() + " (" + origin + ")",
          e);
    }
    LOG.log(Level.DEBUG, "loading settings from {0} ({1})", path.toAbsolutePath(), origin);
    return parse(bytes, path.toAbsolutePath().toString());
  }

  private static Settings fromResource(URL resource) {
    byte[] bytes;
    try (InputStream in = resource.openStream()) {
      bytes = in.readAllBytes();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read " + resource, e);
    }
    LOG.log(Level.DEBUG, "loading settings from class-path resource {0}", resource);
    return parse(bytes, resource.toString());
  }

  /** Parses file contents; every error names {@code source}. */
  private static Settings parse(byte[] bytes, String source) {
    Properties properties = new Properties();
    try {
      properties.load(new StringReader(decode(bytes)));
      return Settings.fromProperties(properties);
    } catch (IllegalArgumentException e) {
      // Both Properties.load (a bad \\u escape) and Settings report problems this way.
      throw new IllegalArgumentException(source + ": " + e.getMessage(), e);
    } catch (IOException e) {
      throw new AssertionError("a StringReader does not fail", e);
    }
  }

  /**
   * UTF-8, falling back to ISO-8859-1 when the bytes are not valid UTF-8: the rule of
   * {@link java.util.PropertyResourceBundle}, so that both modern files and old Latin-1 files
   * (the historical {@code .properties} encoding) read as written.
   */
  private static String decode(byte[] bytes) {
    try {
      return StandardCharsets.UTF_8.newDecoder().decode(ByteBuffer.wrap(bytes)).toString();
    } catch (CharacterCodingException e) {
      return new String(bytes, StandardCharsets.ISO_8859_1);
    }
  }

  private static String blankToNull(String s) {
    return s == null || s.isBlank() ? null : s.trim();
  }
}
