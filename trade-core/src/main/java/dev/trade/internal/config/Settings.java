package dev.trade.internal.config;

import java.time.Duration;
import java.util.Properties;

/** Placeholder until the configuration lands: defaults only. */
public final class Settings {
  private final Properties props;

  private Settings(Properties p) {
    this.props = p;
  }

  public static Settings defaults() {
    return new Settings(new Properties());
  }

  public static Settings load() {
    return defaults();
  }

  public static Settings fromProperties(Properties p) {
    return new Settings((Properties) p.clone());
  }

  public Settings with(String key, String value) {
    Properties p = (Properties) props.clone();
    p.setProperty(key, value);
    return new Settings(p);
  }

  public String containerName() {
    return props.getProperty("CONTAINERNAME", "");
  }

  public boolean copyDataForLocalInvokes() {
    return Boolean.parseBoolean(props.getProperty("COPYDATAFORLOCALINVOKES", "false"));
  }

  public Duration callTimeout() {
    return Duration.ofMillis(Long.parseLong(props.getProperty("CALLTIMEOUT", "30000")));
  }
}
