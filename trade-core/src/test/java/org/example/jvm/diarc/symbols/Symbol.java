package org.example.jvm.diarc.symbols;

/** Like DIARC's {@code Symbol}: a name and its type. */
public record Symbol(String name, String type) {}
