package dev.trade.internal.call;

import java.util.Objects;
import java.util.UUID;

/**
 * Who makes a call: the container it comes from (for a remote call, the CALL frame's source) and
 * the principal it acts for, empty until access control gives it a meaning.
 *
 * @param container the calling container's id
 * @param principal the caller's principal; empty for now
 */
public record Caller(UUID container, String principal) {
  public Caller {
    Objects.requireNonNull(container, "container == null");
    Objects.requireNonNull(principal, "principal == null");
  }

  /** A caller with no principal. */
  public static Caller of(UUID container) {
    return new Caller(container, "");
  }
}
