package dev.trade.examples.launch;

import java.util.concurrent.CountDownLatch;

/**
 * A component for launcher tests that does what its arguments say, in order: {@code print:TEXT}
 * prints a line, {@code pid} prints {@code pid N}, {@code exit:N} exits with status N, and
 * {@code block} waits until the process is stopped.
 */
public final class ScriptMain {
  private ScriptMain() {}

  public static void main(String[] args) throws InterruptedException {
    for (String a : args) {
      if (a.startsWith("print:")) {
        System.out.println(a.substring("print:".length()));
      } else if (a.equals("pid")) {
        System.out.println("pid " + ProcessHandle.current().pid());
      } else if (a.startsWith("exit:")) {
        System.exit(Integer.parseInt(a.substring("exit:".length())));
      } else if (a.equals("block")) {
        new CountDownLatch(1).await();
      } else {
        throw new IllegalArgumentException("unknown step " + a);
      }
    }
  }
}
