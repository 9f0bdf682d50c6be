package org.example.hooks;

import dev.trade.TRADEService;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;

/** Wrappers that record what they are given, in one shared order with the services they wrap. */
public class Recorder {
  /** Every event in order: "S ...", "before ...", "after ...". */
  public final List<String> events;

  public Recorder(List<String> events) {
    this.events = events;
  }

  public Recorder() {
    this(Collections.synchronizedList(new ArrayList<>()));
  }

  @TRADEService
  public void before(Object[] call) {
    events.add("before " + Arrays.deepToString(call));
  }

  @TRADEService
  public void after(Object[] call) {
    events.add("after " + Arrays.deepToString(call));
  }

  /** The second parameter receives the target's failure (null when it returned). */
  @TRADEService
  public void afterWithFailure(Object[] call, Throwable failure) {
    events.add("afterWithFailure " + Arrays.deepToString(call) + " "
        + (failure == null ? "returned" : "threw " + failure.getClass().getSimpleName()
            + (failure.getCause() == null ? "" : " caused by " + failure.getCause().getMessage())));
  }

  /** Mutates what it is given, to show that nothing reaches the call. */
  @TRADEService
  public void vandal(Object[] call) {
    events.add("vandal " + Arrays.deepToString(call));
    for (int i = 0; i < call.length; i++) {
      call[i] = "changed";
    }
  }

  /** Mutates the argument objects it is given (a list), which strict mode keeps from the call. */
  @TRADEService
  @SuppressWarnings("unchecked")
  public void mutateObjects(Object[] call) {
    for (Object o : call) {
      if (o instanceof List<?>) {
        ((List<Object>) o).add("added by a hook");
      }
    }
  }

  @TRADEService
  public void fails(Object[] call) {
    events.add("fails");
    throw new IllegalStateException("a failing hook");
  }

  /** Takes the wrong parameters for a wrapper. */
  @TRADEService
  public void notAWrapper(String s) {}
}
