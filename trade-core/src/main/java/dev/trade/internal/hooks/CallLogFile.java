package dev.trade.internal.hooks;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;

/**
 * A file of lines that is rotated by size: a line that would take the file beyond
 * {@code maxBytes} first renames it to {@code <file>.1} (replacing the one before) and begins a new
 * file, so the log takes at most about twice {@code maxBytes}. Every line is written through at
 * once. Safe for concurrent use (lines are whole and in the order their writers got the lock).
 */
final class CallLogFile implements AutoCloseable {
  private final Path file;
  private final Path rotated;
  private final long maxBytes;
  private OutputStream out; // Guarded by this.
  private long size; // Guarded by this.

  /** Opens {@code file} for appending, creating it (not its directory) if needed. */
  CallLogFile(Path file, long maxBytes) throws IOException {
    this.file = file.toAbsolutePath();
    this.rotated = this.file.resolveSibling(this.file.getFileName() + ".1");
    this.maxBytes = maxBytes;
    open();
  }

  private void open() throws IOException {
    out = Files.newOutputStream(file, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
    size = Files.size(file);
  }

  Path path() {
    return file;
  }

  /** Appends {@code line} and a newline. */
  synchronized void write(String line) throws IOException {
    byte[] bytes = (line + "\n").getBytes(StandardCharsets.UTF_8);
    if (size > 0 && size + bytes.length > maxBytes) {
      out.close();
      Files.move(file, rotated, StandardCopyOption.REPLACE_EXISTING);
      open();
    }
    out.write(bytes);
    out.flush();
    size += bytes.length;
  }

  @Override
  public synchronized void close() throws IOException {
    out.close();
  }
}
