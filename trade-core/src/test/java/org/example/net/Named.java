package org.example.net;

import dev.trade.TRADEService;

/** A service that says whose it is and whom it answers: tells containers apart in a call's reply. */
public class Named {
  private final String name;

  public Named(String name) {
    this.name = name;
  }

  @TRADEService
  public String whoAmI(String caller) {
    return name + " answers " + caller;
  }
}
