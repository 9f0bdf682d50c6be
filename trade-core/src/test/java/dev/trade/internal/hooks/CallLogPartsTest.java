package dev.trade.internal.hooks;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.internal.registry.Registry;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The call log's file rotation, its lines, and the statistics' histogram. */
class CallLogPartsTest {
  @TempDir Path dir;

  @Test
  void theFileIsRotatedBySizeAndKeepsEveryLineOfTheLastTwoFiles() throws IOException {
    Path path = dir.resolve("calls.jsonl");
    List<String> written = new ArrayList<>();
    try (CallLogFile f = new CallLogFile(path, 100)) {
      for (int i = 0; i < 12; i++) {
        String line = "line " + i + " " + "x".repeat(10); // 19 or 20 bytes with its newline
        f.write(line);
        written.add(line);
      }
    }
    List<String> current = Files.readAllLines(path, StandardCharsets.UTF_8);
    List<String> previous = Files.readAllLines(dir.resolve("calls.jsonl.1"),
        StandardCharsets.UTF_8);
    assertTrue(Files.size(path) <= 100 && Files.size(dir.resolve("calls.jsonl.1")) <= 100);
    List<String> kept = new ArrayList<>(previous);
    kept.addAll(current);
    assertEquals(written.subList(written.size() - kept.size(), written.size()), kept);
    assertEquals(List.of("line 10 xxxxxxxxxx", "line 11 xxxxxxxxxx"), current);
  }

  @Test
  void aLineSummarizesArgumentsWithoutCallingTheirToString() {
    Registry registry = new Registry("c-1", "arm", "robot1");
    CallLog log = new CallLog(null, registry);
    Object opaque = new Object() {
      @Override
      public String toString() {
        throw new AssertionError("never called");
      }
    };
    String line = log.line(new Object[] {"say", "a \"quoted\"\nline", 3, 2.5, true, null,
        new int[4], List.of(1, 2), Map.of(), opaque, "x".repeat(100), "ignored result"},
        new IllegalStateException("wrapped", new IllegalArgumentException("no")),
        Map.of("time", 0L, "caller", "c-2", "provider", "c-1", "providerName", "arm",
            "service", "say(java.lang.String)", "nanos", 12_345L));
    assertEquals("{\"time\":\"1970-01-01T00:00:00Z\",\"caller\":\"c-2\",\"callerId\":\"c-2\","
        + "\"service\":\"say(java.lang.String)\",\"provider\":\"arm\",\"providerId\":\"c-1\","
        + "\"args\":[\"a \\\"quoted\\\"\\nline\",3,2.5,true,null,\"int[4]\",\"List(2)\","
        + "\"Map(0)\",\"" + opaque.getClass().getName() + "\",\"" + "x".repeat(80) + "…\"],"
        + "\"micros\":12.345,\"outcome\":\"threw\","
        + "\"error\":\"java.lang.IllegalArgumentException: no\"}", line);
  }

  @Test
  void histogramBucketsHoldTheirValuesWithinAnEighth() {
    for (long v : new long[] {1, 7, 8, 9, 15, 16, 17, 1000, 123_456, 1L << 40, Long.MAX_VALUE}) {
      int b = LatencyHistogram.bucket(v);
      long upper = LatencyHistogram.upperBound(b);
      assertTrue(upper >= v && upper - v <= Math.max(0, v / 8), v + " in bucket up to " + upper);
      assertFalse(b > 0 && LatencyHistogram.upperBound(b - 1) >= v, "lower bucket holds " + v);
    }
    LatencyHistogram h = new LatencyHistogram();
    assertEquals(0, h.percentile(0.5));
    for (int i = 1; i <= 100; i++) {
      h.record(i * 1000L);
    }
    assertEquals(50_000, h.percentile(0.50), 50_000 / 8.0);
    assertEquals(99_000, h.percentile(0.99), 99_000 / 8.0);
    assertTrue(h.percentile(0.50) >= 50_000 && h.percentile(0.99) >= 99_000);
  }
}
