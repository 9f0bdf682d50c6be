package org.example.jvm.diarc.language;

import dev.trade.TRADEService;
import java.util.Set;
import org.example.jvm.diarc.action.Action;
import org.example.jvm.diarc.symbols.Symbol;

/** A DIARC-style component interface: the annotations sit on the interface methods only. */
public interface LanguageInterface {
  @TRADEService
  @Action(kind = Action.Kind.SCRIPT)
  Utterance understand(Set<Symbol> symbols);

  /** The last symbol heard, declared as Object: its class is not in the signature. */
  @TRADEService
  Object lastHeard();
}
