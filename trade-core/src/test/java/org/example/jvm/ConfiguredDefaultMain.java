package org.example.jvm;

import dev.trade.TRADE;
import dev.trade.TRADEContainer;

/**
 * A program that configures the default container in code before its first use, then tries again
 * too late; prints what happened for {@code DefaultContainerInCodeTest}.
 */
public final class ConfiguredDefaultMain {
  private ConfiguredDefaultMain() {}

  public static void main(String[] args) {
    TRADEContainer.Builder builder = TRADEContainer.builder().name("first");
    TRADE.setDefaultContainer(builder);
    TRADE.setDefaultContainer(builder.name("configured-in-code")); // the later call counts
    builder.name("changed-afterwards");
    System.out.println("name " + TRADE.getDefaultContainer().getName());
    try {
      TRADE.setDefaultContainer(TRADEContainer.builder().name("too-late"));
      System.out.println("accepted");
    } catch (IllegalStateException e) {
      System.out.println("refused " + e.getMessage());
    }
  }
}
