package dev.trade.internal.call;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.mockito.ArgumentMatchers.any;
import static org.mockito.Mockito.inOrder;
import static org.mockito.Mockito.mock;
import static org.mockito.Mockito.when;

import dev.trade.TRADEException;
import dev.trade.internal.registry.ServiceDescriptor;
import java.util.List;
import java.util.Set;
import java.util.UUID;
import org.junit.jupiter.api.Test;
import org.mockito.InOrder;

class CallChainTest {
  private static final Caller CALLER = Caller.of(new UUID(0, 1));
  private static final ServiceDescriptor SERVICE = new ServiceDescriptor("c", "c", "h", 1, "s",
      List.of(), List.of(), "void", Set.of(), List.of());

  private static CallLink passing(String tag, StringBuilder trace) {
    return (call, next) -> {
      trace.append(tag).append('>');
      Object r = next.proceed(call);
      trace.append('<').append(tag);
      return r;
    };
  }

  @Test
  void linksRunInOrderAroundTheTerminal() throws TRADEException {
    StringBuilder trace = new StringBuilder();
    CallLink terminal = (call, next) -> {
      trace.append("invoke");
      return "done";
    };
    CallChain chain = new CallChain(List.of(passing("hooks", trace), passing("locks", trace)), terminal);
    assertEquals("done", chain.call(new Invocation(SERVICE, new Object[0], 0, CALLER, CallContext.EMPTY)));
    assertEquals("hooks>locks>invoke<locks<hooks", trace.toString());
  }

  @Test
  void aLinkSeesTheInvocationItsPredecessorPassed() throws TRADEException {
    CallLink first = mock(CallLink.class);
    CallLink terminal = mock(CallLink.class);
    Invocation original = new Invocation(SERVICE, new Object[] {1}, 0, CALLER, CallContext.EMPTY);
    Invocation replaced = original.withArgs(new Object[] {2});
    when(first.proceed(any(), any())).thenAnswer(a -> a.<CallLink.Next>getArgument(1).proceed(replaced));
    when(terminal.proceed(any(), any())).thenReturn("r");
    assertEquals("r", new CallChain(List.of(first), terminal).call(original));
    InOrder order = inOrder(first, terminal);
    order.verify(first).proceed(org.mockito.ArgumentMatchers.eq(original), any());
    order.verify(terminal).proceed(org.mockito.ArgumentMatchers.eq(replaced), any());
  }

  @Test
  void proceedingTwiceIsAnError() {
    CallLink twice = (call, next) -> {
      next.proceed(call);
      return next.proceed(call);
    };
    CallChain chain = new CallChain(List.of(twice), (call, next) -> null);
    IllegalStateException e = assertThrows(IllegalStateException.class,
        () -> chain.call(new Invocation(SERVICE, new Object[0], 0, CALLER, CallContext.EMPTY)));
    assertEquals(twice.getClass().getName() + " called next.proceed() more than once", e.getMessage());
  }

  @Test
  void terminalMayNotProceed() {
    CallChain chain = new CallChain(List.of(), (call, next) -> next.proceed(call));
    assertThrows(IllegalStateException.class, () -> chain.call(new Invocation(SERVICE, new Object[0], 0, CALLER, CallContext.EMPTY)));
  }
}
