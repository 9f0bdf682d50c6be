package org.example.hooks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEBadArgumentsException;
import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADEService;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import dev.trade.testing.Hubs;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/** The call log (JSON lines written by asynchronous after hooks) and the call statistics. */
class CallLogTest {
  private static final Duration WAIT = Duration.ofSeconds(20);
  @RegisterExtension final Hubs net = new Hubs();
  @TempDir Path dir;

  private static List<String> lines(Path file) {
    try {
      return Files.exists(file) ? Files.readAllLines(file, StandardCharsets.UTF_8) : List.of();
    } catch (IOException e) {
      throw new UncheckedIOException(e);
    }
  }

  private static List<String> awaitLines(Path file, int n) {
    Await.until(WAIT, () -> lines(file).size() >= n, n + " lines in " + file);
    return lines(file);
  }

  private static TRADEServiceInfo find(TRADEContainer c, String name) {
    return HooksAcrossContainersTest.find(c, new TRADEServiceConstraints().name(name));
  }

  @Test
  void aCallLogWritesALinePerCallOfTheServicesOfItsGroupsAcrossContainers() throws Exception {
    TRADEContainer logger = net.hub("logger");
    TRADEContainer robot = net.spoke("robot", logger);
    TRADEContainer caller = net.spoke("caller", logger);
    robot.registerAllServices(new Robot(new ArrayList<>()), "robot");
    robot.registerAllServices(new Recorder(), "elsewhere");
    find(logger, "sayText");
    Path file = dir.resolve("calls.jsonl");
    assertEquals(file.toAbsolutePath().toString(), logger.startCallLog(file.toString(), "robot"));

    find(caller, "sayText").call(void.class, "okay");
    assertThrows(TRADEException.class, () -> find(caller, "fail").call(int.class, 7));
    find(caller, "before").call(void.class, (Object) new Object[] {"not logged"});
    List<String> lines = awaitLines(file, 2);
    assertEquals(2, lines.size(), lines.toString());
    String say = lines.stream().filter(l -> l.contains("sayText")).findFirst().orElseThrow();
    assertTrue(say.matches("\\{\"time\":\"[0-9T:.Z-]+\",\"caller\":\"caller\",\"callerId\":\""
        + caller.getId() + "\",\"service\":\"sayText\\(java.lang.String\\)\",\"provider\":\"robot\","
        + "\"providerId\":\"" + robot.getId() + "\",\"args\":\\[\"okay\"\\],\"micros\":[0-9.E]+,"
        + "\"outcome\":\"returned\"}"), say);
    String fail = lines.stream().filter(l -> l.contains("fail(int)")).findFirst().orElseThrow();
    assertTrue(fail.endsWith("\"args\":[7]," + fail.substring(fail.indexOf("\"micros\""),
        fail.indexOf(",\"outcome\"")) + ",\"outcome\":\"threw\",\"error\":"
        + "\"java.lang.IllegalArgumentException: code 7\"}"), fail);

    TRADEBadArgumentsException twice = assertThrows(TRADEBadArgumentsException.class,
        () -> logger.startCallLog(file.toString()));
    assertTrue(twice.getMessage().startsWith("A call log runs in this container already"));

    assertTrue(logger.stopCallLog());
    assertFalse(logger.stopCallLog());
    assertEquals(List.of(), logger.getHooks());
    find(caller, "sayText").call(void.class, "after the end");
    assertEquals(2, lines(file).size());
  }

  @Test
  void theCallLogSettingLogsFromTheStartAndCoversServicesThatJoinLater() throws TRADEException {
    Path file = dir.resolve("setting.jsonl");
    TRADEContainer c = net.keep(TRADEContainer.builder().name("configured")
        .property("CALLLOG", file.toString()).property("CALLLOGGROUPS", "robot, arm").build());
    c.registerAllServices(new Robot(new ArrayList<>()), "arm");
    Await.until(WAIT, () -> c.getHooks().size() == 4, "hooks on the robot's four services");
    find(c, "openGripper").call(boolean.class, 3, "x");
    assertTrue(awaitLines(file, 1).get(0).contains("\"args\":[3,\"x\"]"));
  }

  @Test
  void aBadCallLogSettingNamesTheKey() {
    Path missing = dir.resolve("no-such-directory").resolve("calls.jsonl");
    IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
        () -> net.keep(TRADEContainer.builder().property("CALLLOG", missing.toString()).build()));
    assertTrue(e.getMessage().startsWith("CALLLOG=" + missing + ": The call log cannot write "),
        e.getMessage());
  }

  @Test
  void statisticsCountCallsFailuresAndLatencyPercentiles() throws TRADEException {
    TRADEContainer c = net.keep(TRADEContainer.builder().name("counted").build());
    c.registerAllServices(new Robot(new ArrayList<>()), "robot");
    find(c, "sayText").call(void.class, "before counting");
    c.setCallStatistics(true);
    for (int i = 0; i < 10; i++) {
      find(c, "sayText").call(void.class, "counted");
    }
    assertThrows(TRADEException.class, () -> find(c, "fail").call(int.class, 1));
    c.setCallStatistics(false);
    find(c, "sayText").call(void.class, "after counting");

    List<Map<String, Object>> stats = c.getCallStatistics();
    assertEquals(List.of("fail(int)", "sayText(java.lang.String)", "setCallStatistics(boolean)"),
        stats.stream().map(s -> s.get("service")).toList(), "system services are counted too");
    Map<String, Object> say = stats.get(1);
    assertEquals(List.of("counted", 10L, 0L), List.of(say.get("container"), say.get("calls"),
        say.get("failures")));
    double p50 = (Double) say.get("p50Micros");
    assertTrue(p50 > 0 && (Double) say.get("p99Micros") >= p50, say.toString());
    assertEquals(List.of(1L, 1L), List.of(stats.get(0).get("calls"), stats.get(0).get("failures")));
  }

  /** An after wrapper of three parameters: the array, the failure and the call's details. */
  public static class Detailed {
    final List<Map<String, Object>> details = Collections.synchronizedList(new ArrayList<>());

    @TRADEService
    public void withDetails(Object[] call, Throwable failure, Map<String, Object> details) {
      this.details.add(details);
    }
  }

  @Test
  void aWrapperOfThreeParametersGetsTheCallsDetails() throws TRADEException {
    TRADEContainer provider = net.hub("provider");
    TRADEContainer caller = net.spoke("asker", provider);
    Detailed d = new Detailed();
    provider.registerAllServices(d, "hooks");
    provider.registerAllServices(new Robot(new ArrayList<>()), "robot");
    provider.afterService(find(provider, "withDetails"), find(provider, "sayText"));
    find(caller, "sayText").call(void.class, "hi");

    Map<String, Object> m = d.details.get(0);
    assertEquals(List.of("time", "caller", "provider", "providerName", "service", "nanos"),
        List.copyOf(m.keySet()));
    assertEquals(List.of(caller.getId(), provider.getId(), "provider", "sayText(java.lang.String)"),
        List.of(m.get("caller"), m.get("provider"), m.get("providerName"), m.get("service")));
    assertTrue((Long) m.get("nanos") > 0 && (Long) m.get("time") > 0, m.toString());
  }
}
