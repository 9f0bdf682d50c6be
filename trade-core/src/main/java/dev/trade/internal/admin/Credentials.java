package dev.trade.internal.admin;

/**
 * A credentials string of the API, {@code <principal>:<secret>}: it names a principal and holds
 * what proves it. Text without a colon (such as TRADE's {@code CREDENTIALS} value {@code
 * diarcUser}), null or empty text is anonymous: it proves nothing. Immutable; its
 * {@link #toString()} never shows the secret.
 *
 * @param principal the principal's name
 * @param secret its secret
 */
public record Credentials(String principal, String secret) {
  /** Anonymous: no principal. */
  public static final Credentials ANONYMOUS = new Credentials("", "");

  /**
   * Parses a credentials string.
   *
   * @throws IllegalArgumentException if the name before the colon is not a principal name (the
   *     message never shows the secret)
   */
  public static Credentials parse(String text) {
    if (text == null || text.isEmpty()) {
      return ANONYMOUS;
    }
    int colon = text.indexOf(':');
    if (colon < 0) {
      return ANONYMOUS;
    }
    String name = text.substring(0, colon);
    if (!AccessFile.NAME.matcher(name).matches()) {
      throw new IllegalArgumentException("credentials: '" + name + "' is not a principal name"
          + " (1 to 64 of A-Z a-z 0-9 . _ -); write credentials as <principal>:<secret>");
    }
    return new Credentials(name, text.substring(colon + 1));
  }

  public boolean isAnonymous() {
    return principal.isEmpty();
  }

  @Override
  public String toString() {
    return isAnonymous() ? "anonymous" : principal + ":****";
  }
}
