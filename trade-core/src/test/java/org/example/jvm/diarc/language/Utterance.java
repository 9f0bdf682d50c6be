package org.example.jvm.diarc.language;

import java.util.List;
import org.example.jvm.diarc.symbols.Symbol;

/** Like DIARC's {@code Utterance}: who spoke, and the symbols understood (another package). */
public record Utterance(String speaker, List<Symbol> words) {}
