package org.example.jvm;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trade.TRADEContainer;
import dev.trade.TRADEException;
import dev.trade.TRADESerializationException;
import dev.trade.TRADEServiceConstraints;
import dev.trade.TRADEServiceInfo;
import dev.trade.testing.Await;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.example.jvm.diarc.action.Action;
import org.example.jvm.diarc.language.Utterance;
import org.example.jvm.diarc.symbols.Symbol;
import org.junit.jupiter.api.Test;

/**
 * DIARC's code across two JVMs, with DIARC's configuration (no SERIALIZATIONALLOWLIST on either
 * side): an action database finds a component's services by their {@code @Action} annotation,
 * reads the annotation, and calls one with a {@code Set<Symbol>}, getting a record that holds a
 * {@code List<Symbol>} back; Symbol, Utterance and Action each live in a package of their own, so
 * no package the container allows by default or adds for registered services covers them.
 */
class DiarcAcrossJvmsTest {
  private static final Duration START = Duration.ofSeconds(30);

  @Test
  void servicesAreFoundByAnnotationAndTheirDeclaredValuesTravel() throws Exception {
    try (JvmProcess component = JvmProcess.start(DiarcComponentMain.class, List.of(),
            "CONTAINERNAME=language", "STARTACCEPTINGCONNECTIONS=true", "SERVERIPS=127.0.0.1@0");
        TRADEContainer database = TRADEContainer.builder().name("actiondb")
            .property("CONNECTCONTAINERS", ProviderMain.address(component.awaitLine("READY ", START)))
            .build()) {
      TRADEServiceConstraints hugo = new TRADEServiceConstraints().inGroups("agent:hugo");
      Await.until(START, () -> database.getAvailableServices(hugo).size() == 2,
          "the component's services");

      Collection<TRADEServiceInfo> actions = database.getAvailableServices(Action.class, hugo);
      assertEquals(List.of("understand"), actions.stream().map(s -> s.serviceName).toList());
      TRADEServiceInfo understand = actions.iterator().next();
      Action action = understand.getAnnotations().stream().filter(a -> a instanceof Action)
          .map(a -> (Action) a).findFirst().orElseThrow();
      assertSame(Action.Kind.SCRIPT, action.kind());
      assertEquals("language", understand.getContainerName());

      Set<Symbol> symbols = new LinkedHashSet<>(List.of(new Symbol("cup", "object"),
          new Symbol("kitchen", "location")));
      Utterance heard = understand.call(Utterance.class, symbols);
      assertEquals(new Utterance("hugo", new ArrayList<>(symbols)), heard);

      // A value the signature does not declare still needs the allow-list, and says how.
      TRADEServiceInfo lastHeard = database.getAvailableService(
          new TRADEServiceConstraints().inGroups("agent:hugo").name("lastHeard"));
      TRADESerializationException e = assertThrows(TRADESerializationException.class,
          () -> lastHeard.call(Object.class));
      assertTrue(e.getMessage().contains(Symbol.class.getName())
          && e.getMessage().contains("SERIALIZATIONALLOWLIST"), e.getMessage());
    } catch (TRADEException e) {
      throw new AssertionError(e);
    }
  }
}
