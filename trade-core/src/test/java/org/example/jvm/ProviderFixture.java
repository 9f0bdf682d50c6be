package org.example.jvm;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

/**
 * The fixture of {@link CrossJvmValuesTest} and {@link CrossJvmExceptionsAndAllowListTest}: a
 * {@link ProviderMain} JVM, with a class on its class path that this JVM does not have, and a
 * consumer container here linked to it through real sockets on loopback. One instance per test
 * class, so each class has a provider and a consumer of its own, started before its first test
 * and closed after its last.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
abstract class ProviderFixture {
  static final Duration START = Duration.ofSeconds(30);
  /** A RuntimeException class that exists only on the provider's class path (compiled below). */
  static final String PROVIDER_ONLY = "org.example.jvm.extra.ProviderOnlyException";

  private JvmProcess provider;
  TRADEContainer consumer;
  String providerAddress;
  private final Map<String, TRADEServiceInfo> services = new LinkedHashMap<>();

  @BeforeAll
  void start(@TempDir Path dir) throws Exception {
    Path extraClasses = Files.createDirectories(dir.resolve("classes"));
    provider = ProviderMain.launch(List.of(extraClasses), "CONTAINERNAME=provider",
        "STARTACCEPTINGCONNECTIONS=true", "SERVERIPS=127.0.0.1@0");
    // Compiled while the provider starts; its class loader finds the class when it is first used.
    compileProviderOnlyException(dir.resolve("src"), extraClasses);
    String address = ProviderMain.address(provider.awaitLine("READY ", START));
    providerAddress = address;
    consumer = TRADEContainer.builder().name("consumer")
        .property("CONNECTCONTAINERS", address)
        // Our value types, and the provider-only package (allowed, but its class is not known here).
        .property("SERIALIZATIONALLOWLIST", "org.example.jvm.*;org.example.jvm.extra.*")
        .build();
    TRADEServiceConstraints fromProvider = new TRADEServiceConstraints().inGroups("provider");
    Await.until(START, () -> consumer.getAvailableServices(fromProvider).size()
        == ProviderMain.serviceCount(), "the provider's services");
    for (TRADEServiceInfo s : consumer.getAvailableServices(fromProvider)) {
      services.put(s.serviceName, s);
    }
  }

  @AfterAll
  void stop() {
    try {
      if (consumer != null) {
        consumer.close();
      }
    } finally {
      if (provider != null) {
        provider.close();
      }
    }
  }

  /** Compiles the provider-only exception with this JDK's javac, into {@code classes}. */
  private static void compileProviderOnlyException(Path src, Path classes) throws Exception {
    Path file = src.resolve(PROVIDER_ONLY.replace('.', '/') + ".java");
    Files.createDirectories(file.getParent());
    Files.writeString(file, "package org.example.jvm.extra;\n"
        + "public class ProviderOnlyException extends RuntimeException {\n"
        + "  public ProviderOnlyException(String message) { super(message); }\n"
        + "}\n", UTF_8);
    Process javac = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "javac").toString(),
        "-J-XX:TieredStopAtLevel=1", "--release", "17", "-d", classes.toString(), file.toString())
        .redirectErrorStream(true).start();
    String output = new String(javac.getInputStream().readAllBytes(), UTF_8);
    assertTrue(javac.waitFor(30, TimeUnit.SECONDS), "javac did not finish");
    assertEquals(0, javac.exitValue(), "compiling " + file + ":\n" + output);
  }

  /** The provider's service of that name, as the consumer sees it. */
  TRADEServiceInfo service(String name) {
    TRADEServiceInfo s = services.get(name);
    if (s == null) {
      throw new AssertionError("the provider has no service " + name + "; it has " + services.keySet());
    }
    return s;
  }

  /** Sends {@code value} as the one argument of {@code echo(Object)} and returns the reply. */
  Object echo(Object value) throws TRADEException {
    return service("echo").call(Object.class, new Object[] {value});
  }
}
