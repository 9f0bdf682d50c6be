package org.example.jvm.secret;

/**
 * Types in a package that the test JVM's consumer does not allow to be decoded (its allow-list
 * names {@code org.example.jvm.*}, which does not cover subpackages).
 */
public final class Secrets {
  private Secrets() {}

  public record Code(String value) {}

  public static final class SecretException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public SecretException(String message) {
      super(message);
    }
  }
}
