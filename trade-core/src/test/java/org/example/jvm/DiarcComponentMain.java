package org.example.jvm;

import dev.trade.TRADEContainer;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.example.jvm.diarc.language.LanguageInterface;
import org.example.jvm.diarc.language.Utterance;
import org.example.jvm.diarc.symbols.Symbol;

/**
 * A DIARC-style component in a JVM of its own, configured like DIARC's properties files (no
 * SERIALIZATIONALLOWLIST): builds a container from {@code KEY=VALUE} arguments, registers a
 * {@link LanguageComponent} in group {@code agent:hugo}, prints {@code READY <ip@port>} and runs
 * until its standard input ends.
 */
public final class DiarcComponentMain {
  private DiarcComponentMain() {}

  /** The component: implements the interface, carries no annotations of its own. */
  public static final class LanguageComponent implements LanguageInterface {
    private volatile Symbol last;

    @Override
    public Utterance understand(Set<Symbol> symbols) {
      List<Symbol> words = new ArrayList<>(symbols);
      last = words.isEmpty() ? null : words.get(words.size() - 1);
      return new Utterance("hugo", words);
    }

    @Override
    public Object lastHeard() {
      return last;
    }
  }

  public static void main(String[] args) throws Exception {
    TRADEContainer.Builder builder = TRADEContainer.builder();
    for (String a : args) {
      int eq = a.indexOf('=');
      builder.property(a.substring(0, eq), a.substring(eq + 1));
    }
    try (TRADEContainer container = builder.build()) {
      container.registerAllServices(new LanguageComponent(), "agent:hugo");
      System.out.println("READY " + container.getServerAddresses().get(0));
      System.out.flush();
      while (System.in.read() >= 0) {
        // Input only tells us when to stop.
      }
    }
    System.exit(0);
  }
}
