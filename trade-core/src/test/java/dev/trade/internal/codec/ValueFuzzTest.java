package dev.trade.internal.codec;

import static dev.trade.internal.codec.TestTypes.loader;

import dev.trade.TRADESerializationException;
import dev.trade.testing.Findings;
import dev.trade.testing.Mutator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Structured fuzzing of the value decoder (docs/reliability.md): valid encodings of every kind,
 * mutated, each either decodes or fails with a {@link TRADESerializationException} that is not an
 * internal error; nothing else, and no Error, escapes. Its share of {@code -Dtrade.fuzz.inputs}
 * runs with seed {@code -Dtrade.fuzz.seed}.
 */
@Timeout(3_600)
class ValueFuzzTest {
  static final double SHARE = 0.4;

  @Test
  void mutatedValuesDecodeOrFailTyped() throws Exception {
    Codec codec = TestTypes.codec();
    Mutator mutator = new Mutator(Mutator.seed(), HostileInputTest.samples(codec));
    int inputs = Mutator.inputs(SHARE);
    long decoded = 0;
    long refused = 0;
    try (Findings findings = new Findings("value decoder")) {
      for (int i = 0; i < inputs; i++) {
        byte[] input = mutator.next();
        try {
          codec.decode(input, loader());
          decoded++;
        } catch (TRADESerializationException e) {
          refused++;
          if (e.getMessage() == null || e.getMessage().startsWith("internal decoding error")) {
            findings.add(input, e);
          }
        } catch (RuntimeException | Error e) {
          findings.add(input, e);
        }
      }
      findings.report("inputs=" + inputs + " decoded=" + decoded + " refused=" + refused);
      findings.assertNone();
    }
  }
}
