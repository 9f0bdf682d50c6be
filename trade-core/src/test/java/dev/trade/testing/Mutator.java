package dev.trade.testing;

import java.io.ByteArrayOutputStream;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;

/**
 * Structured mutation of valid inputs for the fuzz tests (docs/reliability.md): each input is a
 * sample changed by one to four edits chosen from bit flips, interesting bytes, 16/32/64-bit
 * interesting values, varint and length-field edits, truncation, duplication of a range, insertion
 * and deletion, and splicing with another sample. Everything comes from one {@link Random}, so a
 * run is replayed exactly by its seed ({@link #seed()}, property {@code trade.fuzz.seed}).
 *
 * <p>Not thread-safe: one per fuzzing thread.
 */
public final class Mutator {
  /** The seed a run uses unless {@code -Dtrade.fuzz.seed} says otherwise. */
  public static final long DEFAULT_SEED = 0x7ade_42L;

  private static final int[] INTERESTING_8 = {0x00, 0x01, 0x7f, 0x80, 0xff, 0x10, 0x20, 0x40, 0xfe};
  private static final long[] INTERESTING_32 = {0, 1, -1, 0x7f, 0x80, 0xff, 0x100, 0x7fff, 0x8000,
      0xffff, 0x10000, 0x7fff_ffffL, 0x8000_0000L, 0xffff_ffffL, 64, 4096, 65_536, 1 << 20, 1 << 26};

  private final Random random;
  private final List<byte[]> samples;

  /** @param samples valid inputs to mutate; not empty, not changed by the mutator */
  public Mutator(long seed, List<byte[]> samples) {
    if (samples.isEmpty()) {
      throw new IllegalArgumentException("samples is empty: give at least one valid input");
    }
    this.random = new Random(seed);
    this.samples = List.copyOf(samples);
  }

  /** The seed of this run: {@code -Dtrade.fuzz.seed}, else {@link #DEFAULT_SEED}. */
  public static long seed() {
    return Long.decode(System.getProperty("trade.fuzz.seed", String.valueOf(DEFAULT_SEED)));
  }

  /**
   * How many inputs a target gets: {@code share} of {@code -Dtrade.fuzz.inputs} (the whole run's
   * count over all targets; 20,000 unless set, the short form that runs with every build).
   */
  public static int inputs(double share) {
    return (int) Math.round(Integer.getInteger("trade.fuzz.inputs", 20_000) * share);
  }

  /** The random source of this run, for choices a target makes around the mutation. */
  public Random random() {
    return random;
  }

  /** A sample chosen at random, unchanged. */
  public byte[] sample() {
    return samples.get(random.nextInt(samples.size()));
  }

  /** A mutated copy of a sample chosen at random. */
  public byte[] next() {
    return mutate(sample());
  }

  /** A copy of {@code input} with one to four edits. */
  public byte[] mutate(byte[] input) {
    byte[] b = input.clone();
    for (int edits = 1 + random.nextInt(4); edits > 0; edits--) {
      b = edit(b);
    }
    return b;
  }

  private byte[] edit(byte[] b) {
    if (b.length == 0) {
      return sample().clone();
    }
    int at = random.nextInt(b.length);
    switch (random.nextInt(11)) {
      case 0 -> b[at] ^= (byte) (1 << random.nextInt(8));
      case 1 -> b[at] = (byte) INTERESTING_8[random.nextInt(INTERESTING_8.length)];
      case 2 -> putBigEndian(b, at, 2, interesting(b.length - at));
      case 3, 4 -> putBigEndian(b, at, random.nextBoolean() ? 4 : 8, interesting(b.length - at));
      case 5 -> b = replace(b, at, random.nextInt(3), varint(interesting(b.length - at)));
      case 6 -> b = Arrays.copyOf(b, random.nextInt(b.length));
      case 7 -> {
        int length = 1 + random.nextInt(Math.min(64, b.length - at));
        b = replace(b, at, 0, Arrays.copyOfRange(b, at, at + length));
      }
      case 8 -> {
        byte[] noise = new byte[1 + random.nextInt(8)];
        random.nextBytes(noise);
        b = replace(b, at, 0, noise);
      }
      case 9 -> b = replace(b, at, 1 + random.nextInt(Math.min(16, b.length - at)), new byte[0]);
      default -> {
        byte[] other = sample();
        int from = random.nextInt(other.length + 1);
        b = replace(b, at, b.length - at, Arrays.copyOfRange(other, from, other.length));
      }
    }
    return b;
  }

  /** A value that tends to break length and count checks: edges, and near what is left. */
  private long interesting(int left) {
    return switch (random.nextInt(4)) {
      case 0 -> left - 1 + random.nextInt(3);
      case 1 -> (long) left << (1 + random.nextInt(20));
      default -> INTERESTING_32[random.nextInt(INTERESTING_32.length)] * (random.nextInt(8) == 0 ? -1 : 1);
    };
  }

  private static void putBigEndian(byte[] b, int at, int width, long value) {
    for (int i = 0; i < width && at + i < b.length; i++) {
      b[at + i] = (byte) (value >>> (8 * (width - 1 - i)));
    }
  }

  /** An unsigned LEB128 varint, as the value format writes counts and lengths. */
  private static byte[] varint(long value) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    long v = value;
    while ((v & ~0x7fL) != 0) {
      out.write((int) ((v & 0x7f) | 0x80));
      v >>>= 7;
    }
    out.write((int) v);
    return out.toByteArray();
  }

  private static byte[] replace(byte[] b, int at, int removed, byte[] inserted) {
    int cut = Math.min(removed, b.length - at);
    byte[] r = new byte[b.length - cut + inserted.length];
    System.arraycopy(b, 0, r, 0, at);
    System.arraycopy(inserted, 0, r, at, inserted.length);
    System.arraycopy(b, at + cut, r, at + inserted.length, b.length - at - cut);
    return r;
  }

  /** The start of {@code input} in hex, for a report that lets a finding be read. */
  public static String hex(byte[] input) {
    return HexFormat.of().formatHex(input, 0, Math.min(input.length, 256))
        + (input.length > 256 ? "… (" + input.length + " bytes)" : "");
  }
}
