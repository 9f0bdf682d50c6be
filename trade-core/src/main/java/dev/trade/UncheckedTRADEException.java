package dev.trade;

import java.util.Objects;

/**
 * Wraps a {@link TRADEException} where a method cannot throw it: thrown by a method of a
 * {@linkplain TRADEContainer#proxy(Class) typed proxy} whose interface does not declare
 * {@code TRADEException}. The cause keeps its type, so callers can still tell a missing service
 * from a failed one:
 *
 * <pre>{@code
 * try {
 *   arm.openGripper(3);
 * } catch (UncheckedTRADEException e) {
 *   if (e.getCause() instanceof TRADEServiceNotFoundException) { ... }
 * }
 * }</pre>
 */
public class UncheckedTRADEException extends RuntimeException {
  private static final long serialVersionUID = 1L;

  /**
   * Wraps {@code cause}, taking its message.
   *
   * @param cause the failure; not null
   */
  public UncheckedTRADEException(TRADEException cause) {
    super(Objects.requireNonNull(cause, "cause == null").getMessage(), cause);
  }

  /**
   * The wrapped failure.
   *
   * @return the {@link TRADEException} this one wraps, never null
   */
  @Override
  public synchronized TRADEException getCause() {
    return (TRADEException) super.getCause();
  }
}
